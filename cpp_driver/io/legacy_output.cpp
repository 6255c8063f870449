#include "io/legacy_output.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <system_error>

#include <fmt/format.h>

#include "model/errors.hpp"

namespace sphjet {
namespace fs = std::filesystem;

namespace {

std::string where(const fs::path& path, std::size_t line) {
    return fmt::format("{}:{}", path.string(), line);
}

std::string shorten(const std::string& s) {
    constexpr std::size_t kMax = 80;
    return s.size() <= kMax ? "'" + s + "'" : "'" + s.substr(0, kMax) + "...'";
}

// Parses one Fortran real: accepts E or D exponents, and the exponent without a letter that
// Ew.d writes for |exponent| > 99 ("0.1+100"). Returns false if the token is not a number.
bool parse_fortran_real(std::string tok, double& v) {
    for (char& c : tok)
        if (c == 'd' || c == 'D') c = 'E';
    // "0.12345678+100" / "0.12-100": a sign after a digit starts the exponent.
    for (std::size_t i = 1; i < tok.size(); ++i) {
        if ((tok[i] == '+' || tok[i] == '-') && std::isdigit(static_cast<unsigned char>(tok[i - 1]))) {
            tok.insert(i, 1, 'E');
            break;
        }
    }
    const char* b = tok.c_str();
    char* e = nullptr;
    errno = 0;
    v = std::strtod(b, &e);
    return e != b && *e == '\0';
}

std::vector<std::string> tokens(const std::string& line) {
    std::vector<std::string> t;
    std::istringstream is(line);
    std::string s;
    while (is >> s) t.push_back(s);
    return t;
}

bool blank(const std::string& line) {
    return std::all_of(line.begin(), line.end(), [](char c) { return std::isspace(static_cast<unsigned char>(c)); });
}

std::ifstream open_in(const fs::path& path, const char* what) {
    std::ifstream in(path);
    if (!in) throw InputError(path.string(), fmt::format("cannot open {}", what), "a readable file",
                              fs::exists(path) ? "an unreadable file" : "no such file");
    return in;
}

}  // namespace

std::string fortran_e16_8(double v) {
    constexpr int kWidth = 16;
    std::string body;
    if (std::isnan(v)) {
        body = "NaN";
    } else if (std::isinf(v)) {
        body = v < 0 ? "-Infinity" : "Infinity";
    } else {
        const bool neg = std::signbit(v);
        int exp10 = 0;
        std::string digits = "00000000";
        if (v != 0.0) {
            char buf[40];
            std::snprintf(buf, sizeof buf, "%.7e", std::fabs(v));  // d.dddddddde+XX
            digits = std::string(1, buf[0]) + std::string(buf + 2, 7);
            exp10 = std::atoi(buf + 10) + 1;
        }
        body = (neg ? "-0." : "0.") + digits;
        const int a = std::abs(exp10);
        const char sign = exp10 < 0 ? '-' : '+';
        if (a <= 99)
            body += fmt::format("E{}{:02d}", sign, a);
        else
            body += fmt::format("{}{:03d}", sign, a);
    }
    if (static_cast<int>(body.size()) >= kWidth) return body;
    return std::string(kWidth - body.size(), ' ') + body;
}

void write_part(const fs::path& path, const ParticleSet& ps) {
    const std::size_t n = ps.size();
    std::vector<std::size_t> order(n);
    if (ps.id.empty()) {
        for (std::size_t i = 0; i < n; ++i) order[i] = i;
    } else {
        std::vector<char> seen(n, 0);
        for (std::size_t i = 0; i < n; ++i) {
            const auto k = ps.id[i];
            if (k < 0 || static_cast<std::size_t>(k) >= n || seen[k])
                throw InputError(path.string(), "cannot write PART: particle ids are not a permutation of 0..n-1",
                                 fmt::format("ids in 0..{}", n - 1), fmt::format("id {} at index {}", k, i));
            seen[k] = 1;
            order[k] = i;
        }
    }
    std::string text;
    text.reserve(n * (7 * 16 + 1));
    for (std::size_t k = 0; k < n; ++k) {
        const std::size_t i = order[k];
        for (double v : {ps.x[i], ps.z[i], ps.u[i], ps.w[i], ps.rho[i], ps.p[i], ps.m[i]})
            text += fortran_e16_8(v);
        text += '\n';
    }
    write_file_atomically(path, text, "the particle file");
}

ParticleSet read_part(const fs::path& path, std::size_t nb, std::size_t nbf) {
    nbf = std::min(nbf, nb);
    auto in = open_in(path, "particle file");
    ParticleSet ps;
    std::string line;
    std::size_t lineno = 0;
    while (std::getline(in, line)) {
        ++lineno;
        if (blank(line)) continue;
        const auto t = tokens(line);
        double v[7];
        bool ok = t.size() == 7;
        for (std::size_t j = 0; ok && j < 7; ++j) ok = parse_fortran_real(t[j], v[j]);
        if (!ok)
            throw InputError(where(path, lineno), "malformed particle line",
                             "7 reals (x z u w rho p m)", shorten(line));
        const std::size_t i = ps.size();
        const auto kind = i < nbf  ? ParticleKind::FixedBoundary
                          : i < nb ? ParticleKind::MovingBoundary
                                   : ParticleKind::Fluid;
        ps.push(v[0], v[1], v[2], v[3], v[4], v[5], v[6], kind);
    }
    if (ps.size() < nb)
        throw InputError(path.string(), "too few particles for the boundary count",
                         fmt::format("at least nb = {} lines", nb), fmt::format("{}", ps.size()));
    ps.nb = nb;
    ps.nbf = nbf;
    return ps;
}

DtFile::DtFile(const fs::path& path, bool append)
    : out_(path, "the DT file", append, " time dt1 dt2 dt_new\n") {}

void DtFile::append(const DtRow& r) {
    out_.append(
        fmt::format(" {:16.8E} {:16.8E} {:16.8E} {:16.8E}\n", r.time, r.dt1, r.dt2, r.dt_new));
}

std::vector<DtRow> read_dt(const fs::path& path) {
    auto in = open_in(path, "DT file");
    std::vector<DtRow> rows;
    std::string line;
    std::size_t lineno = 0;
    while (std::getline(in, line)) {
        ++lineno;
        if (blank(line)) continue;
        const auto t = tokens(line);
        double v[4];
        bool ok = t.size() == 4;
        for (std::size_t j = 0; ok && j < 4; ++j) ok = parse_fortran_real(t[j], v[j]);
        if (!ok) {
            if (lineno == 1 && !t.empty() && t[0] == "time") continue;  // the header
            throw InputError(where(path, lineno), "malformed DT row", "4 reals (time dt1 dt2 dt_new)",
                             shorten(line));
        }
        rows.push_back({v[0], v[1], v[2], v[3]});
    }
    return rows;
}

StepsFile::StepsFile(const fs::path& path, bool append)
    : out_(path, "the steps file", append, "# output step time\n") {}

void StepsFile::append(const StepsRow& r) {
    out_.append(fmt::format("{} {} {:.9e}\n", r.output, r.step, r.time));
}

std::vector<StepsRow> read_steps(const fs::path& path) {
    auto in = open_in(path, "steps file");
    std::vector<StepsRow> rows;
    std::string line;
    std::size_t lineno = 0;
    while (std::getline(in, line)) {
        ++lineno;
        if (blank(line) || line.find_first_not_of(" \t") == line.find('#')) continue;
        const auto t = tokens(line);
        StepsRow r;
        bool ok = t.size() == 3;
        if (ok) {
            char* e = nullptr;
            r.output = static_cast<int>(std::strtol(t[0].c_str(), &e, 10));
            ok = *e == '\0';
            r.step = std::strtoll(t[1].c_str(), &e, 10);
            ok = ok && *e == '\0';
            ok = ok && parse_fortran_real(t[2], r.time);
        }
        if (!ok)
            throw InputError(where(path, lineno), "malformed steps row",
                             "output number (integer), step (integer), time (real)", shorten(line));
        rows.push_back(r);
    }
    return rows;
}

IndatSummary read_indat_summary(const fs::path& path) {
    auto in = open_in(path, "INDAT");
    std::vector<std::string> lines;
    std::string line;
    while (std::getline(in, line)) lines.push_back(line);
    auto real_at = [&](std::size_t n, const char* name) {
        double v = 0.0;
        const auto t = n <= lines.size() ? tokens(lines[n - 1]) : std::vector<std::string>{};
        if (t.empty() || !parse_fortran_real(t[0], v))
            throw InputError(where(path, n), fmt::format("cannot read {}", name), "a number",
                             n <= lines.size() ? shorten(lines[n - 1]) : "end of file");
        return v;
    };
    auto count_at = [&](std::size_t n, const char* name) {
        const double v = real_at(n, name);
        if (v < 0 || v != std::floor(v))
            throw InputError(where(path, n), fmt::format("bad {}", name), "a non-negative integer",
                             shorten(lines[n - 1]));
        return static_cast<std::size_t>(v);
    };
    IndatSummary s;
    s.lx = real_at(19, "vlx");
    s.lz = real_at(21, "vlz");
    s.dx = real_at(22, "dx");
    s.dz = real_at(24, "dz");
    s.h = real_at(25, "h");
    s.np = count_at(26, "np");
    s.nb = count_at(27, "nb");
    s.nbf = count_at(28, "nbf");
    s.out = real_at(32, "out");
    if (s.nb > s.np || s.nbf > s.nb)
        throw InputError(path.string(), "inconsistent particle counts", "nbf <= nb <= np",
                         fmt::format("np = {}, nb = {}, nbf = {}", s.np, s.nb, s.nbf));
    return s;
}

bool LegacyRun::has_steps() const {
    return !outputs.empty() &&
           std::all_of(outputs.begin(), outputs.end(), [](const RunOutput& o) { return o.step.has_value(); });
}

bool LegacyRun::has_times() const {
    return !outputs.empty() &&
           std::all_of(outputs.begin(), outputs.end(), [](const RunOutput& o) { return o.time.has_value(); });
}

LegacyRun read_legacy_run(const fs::path& dir) {
    if (!fs::is_directory(dir))
        throw InputError(dir.string(), "not a run directory", "a directory with PART files",
                         fs::exists(dir) ? "a file" : "nothing");
    LegacyRun run;
    run.dir = dir;

    std::map<int, fs::path> parts;  // PART_k by k
    const std::regex part_re(R"(PART_(\d+))");
    for (const auto& e : fs::directory_iterator(dir)) {
        if (!e.is_regular_file()) continue;
        const std::string name = e.path().filename().string();
        std::smatch m;
        if (std::regex_match(name, m, part_re)) parts[std::stoi(m[1])] = e.path();
    }
    if (fs::is_regular_file(dir / "IPART")) run.outputs.push_back({kInitialOutput, dir / "IPART", 0.0, 0, {}});
    for (const auto& [k, p] : parts) run.outputs.push_back({k, p, {}, {}, {}});
    if (fs::is_regular_file(dir / "EPART")) run.outputs.push_back({kFinalOutput, dir / "EPART", {}, {}, {}});
    if (run.outputs.empty())
        throw InputError(dir.string(), "no particle files", "IPART, PART_nnnn or EPART", "none");

    if (fs::is_regular_file(dir / "INDAT")) run.indat = read_indat_summary(dir / "INDAT");
    if (fs::is_regular_file(dir / "DT")) run.dt = read_dt(dir / "DT");
    if (fs::is_regular_file(dir / "steps.txt")) run.steps = read_steps(dir / "steps.txt");

    // Legacy stdout: the k-th "In poute_2D" line is output k (the last one EPART); removed
    // particles are reported as "Particle out of limits: i" (1-based) before the output.
    std::vector<std::vector<std::int64_t>> removed_before;  // per poute call
    if (fs::is_regular_file(dir / "stdout.txt")) {
        auto in = open_in(dir / "stdout.txt", "stdout.txt");
        const std::regex poute_re(R"(In poute_2D, itime =\s*(-?\d+))");
        const std::regex out_re(R"(Particle out of limits:\s*(\d+))");
        std::vector<std::int64_t> removed;
        std::string line;
        while (std::getline(in, line)) {
            std::smatch m;
            if (std::regex_search(line, m, poute_re)) {
                run.stdout_steps.push_back(std::stoll(m[1]));
                removed_before.push_back(removed);
            } else if (std::regex_search(line, m, out_re)) {
                removed.push_back(std::stoll(m[1]) - 1);
            }
        }
    }

    // The k-th output record (1-based; EPART = the last) of DT and stdout.
    for (auto& o : run.outputs) {
        if (o.number == kInitialOutput) continue;
        std::optional<std::size_t> rec;  // 0-based record index in DT / stdout
        auto n_records = std::max(run.dt.size(), run.stdout_steps.size());
        if (o.number > 0) rec = static_cast<std::size_t>(o.number - 1);
        else if (n_records > 0) rec = n_records - 1;
        if (rec) {
            if (*rec < run.dt.size()) o.time = run.dt[*rec].time;
            if (*rec < run.stdout_steps.size()) {
                o.step = run.stdout_steps[*rec];
                o.removed = removed_before[*rec];
            }
        }
    }
    // Ours: steps.txt overrides.
    for (const auto& r : run.steps) {
        for (auto& o : run.outputs) {
            if (o.number == r.output) {
                o.step = r.step;
                o.time = r.time;
            }
        }
    }
    return run;
}

void mark_outside_container(ParticleSet& ps) {
    const DomainBounds d = legacy_domain(ps);
    for (std::size_t i = ps.nb; i < ps.size(); ++i)
        if (ps.x[i] > d.xmax || ps.x[i] < d.xmin || ps.z[i] < d.zmin) ps.active[i] = 0;
}

ParticleSet load_output(const LegacyRun& run, const RunOutput& out, std::optional<std::size_t> nb_override,
                        std::optional<std::size_t> nbf_override) {
    std::optional<std::size_t> nb = nb_override;
    if (!nb && run.indat) nb = run.indat->nb;
    if (!nb)
        throw InputError(run.dir.string(), "the number of boundary particles is unknown",
                         "an INDAT file in the run directory (or --nb)", "no INDAT");
    std::size_t nbf = nbf_override ? *nbf_override : (run.indat && !nb_override ? run.indat->nbf : *nb);
    ParticleSet ps = read_part(out.file, *nb, nbf);
    if (run.indat && ps.size() != run.indat->np)
        throw InputError(out.file.string(), "particle count differs from INDAT",
                         fmt::format("np = {}", run.indat->np), fmt::format("{} lines", ps.size()));
    for (auto id : out.removed)
        if (id >= 0 && static_cast<std::size_t>(id) < ps.size() && ps.kind[id] == static_cast<int>(ParticleKind::Fluid))
            ps.active[id] = 0;
    mark_outside_container(ps);
    return ps;
}

}  // namespace sphjet
