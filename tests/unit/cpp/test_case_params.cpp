// The description of the case parameters (model/case_params.hpp) against the reference page,
// the structs it names and the readers it drives.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "config/modern_case.hpp"
#include "model/case_params.hpp"

using namespace sphjet;

namespace {

std::string read_text(const std::filesystem::path& p) {
    std::ifstream in(p);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

const std::filesystem::path kPage = std::filesystem::path(SPHJET_SOURCE_DIR) / "cases" / "CASE_FORMAT.md";

}  // namespace

// The key tables of the page are the ones the description makes, to the byte.
TEST(CaseParams, PageTablesAreTheDescriptions) {
    const std::string page = read_text(kPage);
    ASSERT_FALSE(page.empty()) << kPage;
    EXPECT_EQ(with_case_format_tables(page), page)
        << "the key tables of cases/CASE_FORMAT.md differ from model/case_params.cpp; write them anew with "
           "`sphjet keys --update cases/CASE_FORMAT.md`";
}

// Every section with keys, and the HDF5 attributes, has its table in the page.
TEST(CaseParams, PageHasATableForEverySection) {
    const std::string page = read_text(kPage);
    std::set<std::string> sections{"hdf5"};
    for (const Param& r : case_params())
        if (!r.key.empty()) sections.insert(section_of(r.key).empty() ? "top" : std::string(section_of(r.key)));
    for (const auto& s : sections)
        EXPECT_NE(page.find("<!-- keys " + s + " -->\n"), std::string::npos) << "no table for " << s;
}

// The rows with an attribute cover SimParams: sorted by address, each member starts where the
// one before ends, give or take padding; a member added without a row leaves a gap.
TEST(CaseParams, AttributesCoverSimParams) {
    const SimParams p;
    struct Span {
        const char* at;
        std::size_t size;
        std::string_view name;
    };
    std::vector<Span> spans;
    std::set<std::string_view> names;
    for (const Param& r : case_params()) {
        if (r.attr.empty()) continue;
        ASSERT_EQ(r.member.owner, &owner_tag<SimParams>) << r.attr;
        EXPECT_TRUE(names.insert(r.attr).second) << "attribute " << r.attr << " twice";
        spans.push_back({static_cast<const char*>(r.member.address(&p)), r.member.size, r.attr});
    }
    std::sort(spans.begin(), spans.end(), [](const Span& a, const Span& b) { return a.at < b.at; });
    const char* end = reinterpret_cast<const char*>(&p);
    for (const Span& s : spans) {
        EXPECT_GE(s.at, end) << s.name << " overlaps the member before it";
        EXPECT_LT(s.at - end, static_cast<std::ptrdiff_t>(s.size)) << "a member without a row before " << s.name;
        end = s.at + s.size;
    }
    EXPECT_LT(reinterpret_cast<const char*>(&p) + sizeof(SimParams) - end, 8) << "a member without a row at the end";
}

// Each row's key type fits the member it names; choices are unique; keys are unique.
TEST(CaseParams, RowsAreConsistent) {
    std::set<std::string_view> keys;
    for (const Param& r : case_params()) {
        if (!r.key.empty()) EXPECT_TRUE(keys.insert(r.key).second) << r.key << " twice";
        EXPECT_FALSE(r.doc.empty()) << r.key << r.attr << " has no doc";
        const auto store = r.member.store;
        if (store == Member::Store::None) {
            EXPECT_TRUE(r.hand & kHandRead) << r.key << ": no member, so it must be read by hand";
            continue;
        }
        if (r.key.empty()) continue;
        switch (r.type) {
            case KeyType::Float: EXPECT_EQ(store, Member::Store::Float) << r.key; break;
            case KeyType::Int: EXPECT_EQ(store, Member::Store::Int) << r.key; break;
            case KeyType::Bool: EXPECT_NE(store, Member::Store::Float) << r.key; break;
            case KeyType::String: EXPECT_FALSE(r.choices.empty()) << r.key; break;
        }
        std::set<std::string_view> names;
        for (const auto& c : r.choices) EXPECT_TRUE(names.insert(c.name).second) << r.key << ": " << c.name;
    }
}

// A plain row is read and echoed through its member: a value set by --set comes back in the
// echo (here one key of each type).
TEST(CaseParams, PlainRowsReachTheMemberAndTheEcho) {
    const std::string minimal =
        "[fluid]\nc0 = 20.0\n[[fluid.block]]\nxmin = 0.0\nxmax = 0.1\nzmin = 0.0\nzmax = 0.1\n"
        "[domain]\nlx = 0.4\nlz = 0.3\n[resolution]\ndx = 0.01\nh_over_dx = 1.3\n";
    const CaseSpec s = parse_modern_case(minimal, "case.toml",
                                         {"numerics.wall_viscosity=2.5e-6", "numerics.filter_period=7",
                                          "time.variable_dt=false", "numerics.kernel=cubic_spline"});
    EXPECT_EQ(s.params.wall_viscosity, 2.5e-6);
    EXPECT_EQ(s.params.filter_period, 7);
    EXPECT_FALSE(s.params.variable_dt);
    EXPECT_EQ(s.params.kernel, KernelType::CubicSpline);
    const std::string echo = write_modern_case(s);
    for (const char* line : {"wall_viscosity = 2.5e-06", "filter_period = 7", "variable_dt = false",
                             "kernel = \"cubic_spline\""})
        EXPECT_NE(echo.find(line), std::string::npos) << line << "\n" << echo;
}
