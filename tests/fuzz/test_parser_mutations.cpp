// Parser robustness, deterministically: every input the three readers (legacy case file,
// INDAT/IPART/NORMALS.init, modern TOML with overrides) are given must either be accepted or
// give a sphjet::InputError; an accepted case must also go through the generator (InputError
// allowed) and give finite parameters and particles (fuzz_harness.hpp). Anything else (another
// exception type, a non-finite value let through) is a failure, and the input that caused it
// is written to <build>/tests/fuzz/failures/<parser>/ for the regression corpus.
//
// The inputs: the seeds (tests/fuzz/corpus, tests/data/bad_cases, tests/fuzz/regressions) and
// a few thousand mutants per parser made by a fixed-seed generator (byte flips, line
// deletions, duplications and swaps, numbers replaced by extremes such as 0, -1, 1e308, nan,
// inf, 99999999999, huge repeats, truncation; for the modern format, random override strings
// too). The same inputs on every run and every platform (std::mt19937_64 is specified bit
// for bit; no std:: distributions, whose results vary between libraries).
// The libFuzzer targets (tools/fuzz.sh) search the same space without the bound.
#include <algorithm>
#include <array>
#include <cctype>
#include <chrono>
#include <cstdio>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <string_view>
#include <typeinfo>
#include <vector>

#include <gtest/gtest.h>
#include <unistd.h>

#include "config/modern_case.hpp"
#include "fuzz_harness.hpp"

namespace fs = std::filesystem;
using namespace sphjet::fuzz;

namespace {

const fs::path kSource = SPHJET_SOURCE_DIR;
const fs::path kFuzzDir = kSource / "tests" / "fuzz";
const fs::path kFailures = fs::path(SPHJET_FUZZ_BINARY_DIR) / "failures";

// Generate only up to this many particles: the seeds make a few hundred, and an accepted
// mutant rarely more than a few thousand; the cap bounds the few that would make millions.
constexpr double kGenerateCap = 20000;

std::string read_file(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

std::vector<std::pair<std::string, std::string>> files_in(const std::vector<fs::path>& dirs) {
    std::vector<std::pair<std::string, std::string>> out;
    for (const auto& d : dirs) {
        if (!fs::is_directory(d)) continue;
        std::vector<fs::path> paths;
        for (const auto& e : fs::directory_iterator(d))
            if (e.is_regular_file() && e.path().filename().string()[0] != '.') paths.push_back(e.path());
        std::sort(paths.begin(), paths.end());
        for (const auto& p : paths) out.emplace_back(p.string(), read_file(p));
    }
    return out;
}

// ---------------------------------------------------------------------------------------
// The mutator
// ---------------------------------------------------------------------------------------

constexpr std::array<const char*, 30> kExtremes = {
    "0", "-1", "1", "1e308", "-1e308", "1e309", "nan", "inf", "-inf", "+inf", "99999999999",
    "999999999999", "2147483648", "-2147483649", "9223372036854775807", "9223372036854775808",
    "18446744073709551616", "1e-308", "4.9e-324", "1e-320", "3.5e38", "1e39", "1.0d300", "-0",
    "0.0", "1e", ".", "-", "0x10", "1_000"};

constexpr std::array<char, 24> kBytes = {',', ' ', '\t', '\n', '\r', '.', 'e', 'E', 'd', '-', '+',
                                         '0', '1', '9', '[', ']', '=', '"', '\'', '#', '{',
                                         '\0', '\x7f', '\xff'};

class Mutator {
public:
    explicit Mutator(std::uint64_t seed) : rng_(seed) {}

    std::size_t below(std::size_t n) { return n == 0 ? 0 : static_cast<std::size_t>(rng_() % n); }
    bool chance(int percent) { return below(100) < static_cast<std::size_t>(percent); }
    const char* extreme() { return kExtremes[below(kExtremes.size())]; }

    std::string mutate(std::string s) {
        const std::size_t n = 1 + below(3);
        for (std::size_t k = 0; k < n; ++k) s = once(std::move(s));
        return s;
    }

private:
    static std::vector<std::string> lines(const std::string& s) {
        std::vector<std::string> out;
        std::size_t b = 0;
        while (b <= s.size()) {
            const auto e = s.find('\n', b);
            if (e == std::string::npos) {
                if (b < s.size()) out.push_back(s.substr(b));
                break;
            }
            out.push_back(s.substr(b, e - b));
            b = e + 1;
        }
        return out;
    }
    static std::string unlines(const std::vector<std::string>& ls) {
        std::string s;
        for (const auto& l : ls) s += l + '\n';
        return s;
    }

    // [begin, end) of every number in s: a digit (or a sign or dot before one) not preceded by
    // a letter, digit or dot, and what follows of [0-9.eEdD+-].
    static std::vector<std::pair<std::size_t, std::size_t>> numbers(const std::string& s) {
        std::vector<std::pair<std::size_t, std::size_t>> out;
        const auto digit = [](char c) { return c >= '0' && c <= '9'; };
        const auto word = [&](char c) { return digit(c) || std::isalpha(static_cast<unsigned char>(c)) || c == '.' || c == '_'; };
        for (std::size_t i = 0; i < s.size(); ++i) {
            if (!digit(s[i]) || (i > 0 && word(s[i - 1]))) continue;
            std::size_t b = i;
            if (b > 0 && (s[b - 1] == '-' || s[b - 1] == '+')) --b;
            std::size_t e = i;
            while (e < s.size() && (digit(s[e]) || std::string_view(".eEdD+-").find(s[e]) != std::string_view::npos)) ++e;
            out.emplace_back(b, e);
            i = e;
        }
        return out;
    }

    std::string once(std::string s) {
        switch (below(12)) {
            case 0: {  // flip bits of one byte
                if (s.empty()) return s;
                s[below(s.size())] ^= static_cast<char>(1u << below(8));
                return s;
            }
            case 1: {  // replace a byte by a separator, digit or odd byte
                if (s.empty()) return s;
                s[below(s.size())] = kBytes[below(kBytes.size())];
                return s;
            }
            case 2: {  // delete a line
                auto ls = lines(s);
                if (!ls.empty()) ls.erase(ls.begin() + static_cast<long>(below(ls.size())));
                return unlines(ls);
            }
            case 3: {  // duplicate a line
                auto ls = lines(s);
                if (!ls.empty()) {
                    const std::size_t i = below(ls.size());
                    ls.insert(ls.begin() + static_cast<long>(i), ls[i]);
                }
                return unlines(ls);
            }
            case 4: {  // swap two lines
                auto ls = lines(s);
                if (ls.size() > 1) std::swap(ls[below(ls.size())], ls[below(ls.size())]);
                return unlines(ls);
            }
            case 5:
            case 6:
            case 7: {  // a number replaced by an extreme (the most fruitful change: weighted)
                const auto nums = numbers(s);
                if (nums.empty()) return s;
                const auto [b, e] = nums[below(nums.size())];
                return s.replace(b, e - b, extreme());
            }
            case 8: {  // huge repeats: a line many times, or a long run in one place
                if (chance(50)) {
                    auto ls = lines(s);
                    if (ls.empty()) return s;
                    const std::size_t i = below(ls.size());
                    ls.insert(ls.begin() + static_cast<long>(i), 2000 + below(3000), ls[i]);
                    return unlines(ls);
                }
                const char c = "9 0,[{.\n"[below(8)];
                return s.insert(below(s.size() + 1), 5000 + below(20000), c);
            }
            case 9: {  // a number with hundreds of digits
                const auto nums = numbers(s);
                if (nums.empty()) return s;
                const auto [b, e] = nums[below(nums.size())];
                return s.replace(b, e - b, "1" + std::string(300 + below(400), '0'));
            }
            case 10:  // truncation
                return s.substr(0, below(s.size() + 1));
            default: {  // a few random bytes inserted
                const std::size_t n = 1 + below(4);
                std::string ins;
                for (std::size_t k = 0; k < n; ++k) ins += static_cast<char>(rng_() & 0xff);
                return s.insert(below(s.size() + 1), ins);
            }
        }
    }

    std::mt19937_64 rng_;
};

// A random override: a schema key (with a random index for arrays of tables) or a malformed
// path, and a value that is an extreme, a word, or a TOML snippet.
std::string random_override(Mutator& m) {
    static const std::vector<std::string> keys = sphjet::modern_case_keys();
    static const std::array<const char*, 9> indices = {"0", "1", "0", "-1", "", "x", "99999999999999999999",
                                                       "18446744073709551615", "0]["};
    static const std::array<const char*, 16> odd_paths = {
        "", ".", "..", "a..b", "fluid.block[0]", "fluid.block", "numerics", "fluid.block.u0",
        "fluid.block[0].nope", "[[obstacle]]", "obstacle[0].xmin.extra", "format_version[0]",
        "fluid.rho0[2]", " fluid . rho0 ", "numerics.kernle", "\"numerics\".kernel"};
    static const std::array<const char*, 17> values = {
        "", "true", "\"wendland\"", "wendland", "[1, 2]", "{ a = 1 }", "1979-05-27", "1e", "'x'",
        "\"\\u0000\"", "\"unterminated", "1\\nw = 2", "1\\n[^", "nan", "-inf", "0x7fffffffffffffff", "= ="};
    std::string path;
    if (m.chance(80)) {
        path = keys[m.below(keys.size())];
        for (auto p = path.find("[]"); p != std::string::npos; p = path.find("[]", p + 1))
            path.replace(p, 2, std::string("[") + indices[m.below(indices.size())] + "]");
    } else {
        path = odd_paths[m.below(odd_paths.size())];
    }
    const std::string value = m.chance(50) ? m.extreme() : values[m.below(values.size())];
    if (m.chance(5)) return path + value;  // no '='
    return path + (m.chance(20) ? " = " : "=") + value;
}

// ---------------------------------------------------------------------------------------
// Running inputs
// ---------------------------------------------------------------------------------------

struct Tally {
    std::size_t inputs = 0, rejected = 0, accepted = 0, generated = 0, failures = 0;
    double slowest_s = 0;
    std::string slowest_name;
};

template <class Run>
void check_input(const std::string& parser, const std::string& name, const std::string& data,
                 Tally& t, Run&& run) {
    ++t.inputs;
    const auto t0 = std::chrono::steady_clock::now();
    std::string failure;
    try {
        switch (run(data)) {
            case Outcome::Rejected: ++t.rejected; break;
            case Outcome::Accepted: ++t.accepted; break;
            case Outcome::Generated: ++t.generated; break;
        }
    } catch (const HarnessViolation& e) {
        failure = std::string("HarnessViolation: ") + e.what();
    } catch (const std::exception& e) {
        failure = std::string(typeid(e).name()) + ": " + e.what();
    } catch (...) {
        failure = "an exception that is not a std::exception";
    }
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (s > t.slowest_s) t.slowest_s = s, t.slowest_name = name;
    if (failure.empty()) return;
    ++t.failures;
    fs::create_directories(kFailures / parser);
    const fs::path saved = kFailures / parser / ("failure_" + std::to_string(t.failures));
    std::ofstream(saved, std::ios::binary) << data;
    if (t.failures <= 10)
        ADD_FAILURE() << parser << " input " << name << " (saved as " << saved.string()
                      << ") escaped the InputError contract: " << failure;
}

void report(const std::string& parser, const Tally& t) {
    std::printf("%s: %zu inputs: %zu rejected (InputError), %zu accepted (not generated), "
                "%zu accepted and generated; %zu failures; slowest %.3f s (%s)\n",
                parser.c_str(), t.inputs, t.rejected, t.accepted, t.generated, t.failures, t.slowest_s,
                t.slowest_name.c_str());
    EXPECT_EQ(t.failures, 0u) << parser << ": " << t.failures << " inputs escaped the contract";
}

// Seeds, then `mutants` mutants round-robin over the seeds.
template <class Run>
Tally campaign(const std::string& parser, const std::vector<fs::path>& seed_dirs, std::size_t mutants,
               std::uint64_t rng_seed, Run&& run, bool modern = false) {
    const auto seeds = files_in(seed_dirs);
    EXPECT_FALSE(seeds.empty()) << "no seeds for " << parser;
    Tally t;
    if (seeds.empty()) return t;
    for (const auto& [name, data] : seeds) check_input(parser, name, data, t, run);
    Mutator m(rng_seed);
    for (std::size_t k = 0; k < mutants; ++k) {
        const auto& [name, data] = seeds[k % seeds.size()];
        std::string mutant = m.mutate(data);
        if (modern && m.chance(35)) {
            if (mutant.find(kOverridesMarker) == std::string::npos)
                mutant += "\n" + std::string(kOverridesMarker) + "\n";
            for (std::size_t n = 1 + m.below(3); n > 0; --n) mutant += random_override(m) + "\n";
        }
        check_input(parser, name + " mutant " + std::to_string(k), mutant, t, run);
    }
    return t;
}

// The INDAT files of each input are written here: /dev/shm where there is one (a RAM disk,
// much faster than the build tree for thousands of small files), else the temporary directory.
fs::path scratch_dir(const std::string& name) {
    const fs::path shm = "/dev/shm";
    return (fs::is_directory(shm) ? shm : fs::temp_directory_path()) /
           ("sphjet-parser-mutations-" + name + "-" + std::to_string(::getpid()));
}

}  // namespace

TEST(ParserMutations, SeedsAreValid) {
    // The seeds are what the mutants start from: each must be accepted (bad_cases are not
    // seeds of this kind), and the INDAT seeds must read back through the marker format.
    for (const auto& [name, data] : files_in({kFuzzDir / "corpus" / "legacy"}))
        EXPECT_NE(run_legacy(data, kGenerateCap), Outcome::Rejected) << name;
    for (const auto& [name, data] : files_in({kFuzzDir / "corpus" / "modern"}))
        EXPECT_NE(run_modern(data, kGenerateCap), Outcome::Rejected) << name;
    for (const auto& [name, data] : files_in({kFuzzDir / "corpus" / "indat"}))
        if (name.find("_indat_only") == std::string::npos)
            EXPECT_EQ(run_indat(data, scratch_dir("seeds")), Outcome::Generated) << name;
    fs::remove_all(scratch_dir("seeds"));
}

TEST(ParserMutations, LegacyCaseReaderGivesOnlyInputErrors) {
    const Tally t = campaign(
        "legacy",
        {kFuzzDir / "corpus" / "legacy", kSource / "tests" / "data" / "bad_cases", kFuzzDir / "regressions" / "legacy"},
        5000, 0x5eed1e9ac7ULL, [](const std::string& d) { return run_legacy(d, kGenerateCap); });
    report("legacy", t);
    EXPECT_GT(t.generated, 100u) << "the mutants should not all be rejected";
}

TEST(ParserMutations, IndatReaderGivesOnlyInputErrors) {
    const fs::path dir = scratch_dir("indat");
    const Tally t = campaign("indat", {kFuzzDir / "corpus" / "indat", kFuzzDir / "regressions" / "indat"}, 3000,
                             0x5eedd47aULL, [&](const std::string& d) { return run_indat(d, dir); });
    fs::remove_all(dir);
    report("indat", t);
    EXPECT_GT(t.generated, 100u) << "the mutants should not all be rejected";
}

TEST(ParserMutations, ModernCaseReaderGivesOnlyInputErrors) {
    const Tally t = campaign(
        "modern", {kFuzzDir / "corpus" / "modern", kFuzzDir / "regressions" / "modern"}, 4000, 0x5eed70a1ULL,
        [](const std::string& d) { return run_modern(d, kGenerateCap); }, true);
    report("modern", t);
    EXPECT_GT(t.generated, 100u) << "the mutants should not all be rejected";
}
