// Output writers on a disk that fills up (io/file_write.hpp and its users).
//
// What each test checks: a write that fails part-way throws WriteError naming the file and
// the cause from errno, leaves no temporary file, and leaves the previous version of the
// file (and every earlier file) as it was and readable; an appended text file keeps whole
// rows only.
//
// How the disk fills, from the most portable to the most real:
//  - RLIMIT_FSIZE: the kernel refuses writes past a file size limit (EFBIG, "File too
//    large"), part-way through a write() like a full disk, with no privileges. It drives
//    every writer through the same failure paths as ENOSPC.
//  - /dev/full: every write fails with ENOSPC ("No space left on device").
//  - a 256 kB tmpfs mounted for the test (root only; skipped with a message otherwise): a
//    real full file system, filled by snapshots until one does not fit.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/mount.h>
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "io/checkpoint.hpp"
#include "io/file_write.hpp"
#include "io/h5_util.hpp"
#include "io/hdf5_output.hpp"
#include "io/legacy_output.hpp"
#include "model/errors.hpp"

namespace fs = std::filesystem;
using namespace sphjet;

namespace {

fs::path fresh_dir(const std::string& name) {
    const fs::path d = fs::temp_directory_path() /
                       ("sphjet_test_disk_" + name + "_" + std::to_string(::getpid()));
    fs::remove_all(d);
    fs::create_directories(d);
    return d;
}

std::string slurp(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

std::vector<std::string> temporaries(const fs::path& dir) {
    std::vector<std::string> out;
    for (const auto& e : fs::directory_iterator(dir)) {
        const std::string n = e.path().filename().string();
        if (n.find(".tmp") != std::string::npos) out.push_back(n);
    }
    return out;
}

// Files may grow to `bytes` while it lives (SIGXFSZ ignored, so writes fail with EFBIG).
class FileSizeLimit {
public:
    explicit FileSizeLimit(rlim_t bytes) {
        getrlimit(RLIMIT_FSIZE, &old_);
        old_handler_ = signal(SIGXFSZ, SIG_IGN);
        rlimit r = old_;
        r.rlim_cur = bytes;
        setrlimit(RLIMIT_FSIZE, &r);
    }
    ~FileSizeLimit() {
        setrlimit(RLIMIT_FSIZE, &old_);
        signal(SIGXFSZ, old_handler_);
    }
    FileSizeLimit(const FileSizeLimit&) = delete;
    FileSizeLimit& operator=(const FileSizeLimit&) = delete;

private:
    rlimit old_{};
    sighandler_t old_handler_ = nullptr;
};

ParticleSet particles(std::size_t n, double shift) {
    ParticleSet ps;
    for (std::size_t i = 0; i < n; ++i) {
        ps.push(0.001 * static_cast<double>(i) + shift, 0.5, 0.1, -0.2, 1000.0, 12.5, 0.01,
                ParticleKind::Fluid);
        ps.id.back() = static_cast<std::int64_t>(i);
    }
    return ps;
}

RunState state_at(double time, std::int64_t step) {
    RunState s;
    s.time = time;
    s.step = step;
    s.dt = 1e-5;
    return s;
}

// The WriteError of calling f, or a failed test.
template <class F>
WriteError write_error_of(F&& f) {
    try {
        f();
    } catch (const WriteError& e) {
        return e;
    }
    ADD_FAILURE() << "no WriteError";
    return WriteError("", 0, "");
}

}  // namespace

TEST(DiskFull, AtomicFileKeepsTheOldVersionAndRemovesItsTemporary) {
    const fs::path dir = fresh_dir("atomic");
    const fs::path f = dir / "PART_0001";
    write_file_atomically(f, "old content\n", "the particle file");
    const std::string big(200000, 'x');
    const WriteError e = write_error_of([&] {
        FileSizeLimit limit(50000);  // the write stops a quarter of the way
        write_file_atomically(f, big, "the particle file");
    });
    EXPECT_EQ(e.error_number(), EFBIG);
    EXPECT_EQ(e.path(), f.string());
    const std::string msg = e.what();
    EXPECT_NE(msg.find(f.string() + ": cannot write the particle file: " + std::strerror(EFBIG)),
              std::string::npos)
        << msg;
    EXPECT_EQ(slurp(f), "old content\n");
    EXPECT_TRUE(temporaries(dir).empty());
    // With room again the same write succeeds.
    write_file_atomically(f, big, "the particle file");
    EXPECT_EQ(slurp(f), big);
    fs::remove_all(dir);
}

TEST(DiskFull, AppendedRowsAreWholeOrAbsent) {
    const fs::path dir = fresh_dir("append");
    const fs::path f = dir / "DT";
    DtFile dt(f);
    dt.append({0.01, 1e-4, 2e-4, 1e-4});
    const std::string before = slurp(f);
    const WriteError e = write_error_of([&] {
        // Room for the header, one row and 10 more bytes: the next row is written in part.
        FileSizeLimit limit(before.size() + 10);
        dt.append({0.02, 1e-4, 2e-4, 1e-4});
    });
    EXPECT_EQ(e.error_number(), EFBIG);
    EXPECT_NE(std::string(e.what()).find("DT: cannot write the DT file"), std::string::npos)
        << e.what();
    EXPECT_EQ(slurp(f), before) << "the half row was not cut back";
    dt.append({0.03, 1e-4, 2e-4, 1e-4});  // room again: the file goes on with whole rows
    const auto rows = read_dt(f);
    ASSERT_EQ(rows.size(), 2u);
    EXPECT_EQ(rows[1].time, 0.03);

    // A resumed file drops a half row left by a crash (no newline at the end).
    std::ofstream(f, std::ios::app) << " 0.4000";
    const std::string whole = slurp(f).substr(0, slurp(f).size() - 7);
    DtFile resumed(f, true);
    EXPECT_EQ(slurp(f), whole);
    fs::remove_all(dir);
}

TEST(DiskFull, DevFullGivesNoSpaceLeftOnDevice) {
    if (!fs::exists("/dev/full")) GTEST_SKIP() << "no /dev/full on this system";
    const WriteError e =
        write_error_of([] { AppendFile f("/dev/full", "the run log", true, "x\n"); });
    EXPECT_EQ(e.error_number(), ENOSPC);
    const std::string msg = e.what();
    EXPECT_NE(msg.find("/dev/full: cannot write the run log: No space left on device"),
              std::string::npos)
        << msg;
    EXPECT_NE(msg.find("expected room for 2 B on the file system"), std::string::npos) << msg;
}

TEST(DiskFull, SnapshotAndIndexStayReadable) {
    const fs::path dir = fresh_dir("snap");
    Hdf5Writer w(dir, SimParams{}, "test");
    const ParticleSet small = particles(100, 0.0);
    w.write(small, state_at(0.0, 0));
    const std::string index = slurp(w.xdmf_path());
    const ParticleSet big = particles(20000, 1.0);  // about 1.3 MB of raw data
    const WriteError e = write_error_of([&] {
        FileSizeLimit limit(200000);
        w.write(big, state_at(0.1, 10));
    });
    EXPECT_EQ(e.error_number(), EFBIG);
    EXPECT_EQ(e.path(), (dir / "snap_000001.h5").string());
    EXPECT_FALSE(fs::exists(dir / "snap_000001.h5"));
    EXPECT_TRUE(temporaries(dir).empty());
    EXPECT_EQ(slurp(w.xdmf_path()), index);  // the index still lists snapshot 0 only
    const Snapshot s = read_snapshot(dir / "snap_000000.h5");
    EXPECT_EQ(s.particles.x, small.x);
    fs::remove_all(dir);
}

TEST(DiskFull, CheckpointKeepsTheLastGoodOne) {
    const fs::path dir = fresh_dir("ckpt");
    const ParticleSet first = particles(100, 0.0);
    write_checkpoint(dir, first, state_at(0.05, 5), SimParams{});
    const WriteError e = write_error_of([&] {
        FileSizeLimit limit(100000);
        write_checkpoint(dir, particles(20000, 1.0), state_at(0.1, 10), SimParams{});
    });
    EXPECT_EQ(e.error_number(), EFBIG);
    EXPECT_NE(std::string(e.what()).find("checkpoint.h5: cannot write the checkpoint: "),
              std::string::npos)
        << e.what();
    EXPECT_TRUE(temporaries(dir).empty());
    const Checkpoint c = read_checkpoint(dir);
    EXPECT_EQ(c.state.step, 5);
    EXPECT_EQ(c.particles.x, first.x);
    fs::remove_all(dir);
}

// HDF5 files are built in memory (io/h5_util.hpp): the first in a thread's reusable buffer,
// a second one open at the same time in memory of its own. Both must come out whole.
TEST(DiskFull, TwoInMemoryFilesAtOnceBothReadBack) {
    const fs::path dir = fresh_dir("two");
    h5::File a = h5::create_file(dir / "a.h5");
    h5::File b = h5::create_file(dir / "b.h5");
    h5::write_attr(a, "name", std::string("a"));
    h5::write_attr(b, "name", std::string("b"));
    const std::vector<double> big(300000, 1.5);  // grows b past its first allocation
    h5::write_array(b, "v", std::span<const double>(big));
    h5::write_file(b, dir / "b.h5", "b");
    h5::write_file(a, dir / "a.h5", "a");
    EXPECT_EQ(h5::read_attr_string(h5::open_file(dir / "a.h5"), "name"), "a");
    h5::File rb = h5::open_file(dir / "b.h5");
    EXPECT_EQ(h5::read_attr_string(rb, "name"), "b");
    EXPECT_EQ(h5::read_doubles(rb, "v"), big);
    rb.reset();
    // and the buffer is free again for the next file
    h5::File c = h5::create_file(dir / "c.h5");
    h5::write_attr(c, "name", std::string("c"));
    h5::write_file(c, dir / "c.h5", "c");
    EXPECT_EQ(h5::read_attr_string(h5::open_file(dir / "c.h5"), "name"), "c");
    fs::remove_all(dir);
}

TEST(DiskFull, RemoveTemporariesTakesOnlyTemporaries) {
    const fs::path dir = fresh_dir("leftovers");
    for (const char* n : {"snap_000003.h5.tmp", "INDAT.tmp-sphjet", "snap_000002.h5", "DT"})
        std::ofstream(dir / n) << "x";
    auto removed = remove_temporaries(dir);
    std::sort(removed.begin(), removed.end());
    EXPECT_EQ(removed, (std::vector<std::string>{"INDAT.tmp-sphjet", "snap_000003.h5.tmp"}));
    EXPECT_TRUE(fs::exists(dir / "snap_000002.h5"));
    EXPECT_TRUE(fs::exists(dir / "DT"));
    fs::remove_all(dir);
}

// A real full file system: snapshots of 20000 particles (about 1.4 MB each) and a checkpoint
// on a 4 MB tmpfs, until one does not fit.
TEST(DiskFull, RealTmpfsFillsUp) {
    const fs::path dir = fresh_dir("tmpfs");
    if (::mount("tmpfs", dir.c_str(), "tmpfs", 0, "size=4m") != 0) {
        const int err = errno;
        fs::remove_all(dir);
        GTEST_SKIP() << "cannot mount a 4 MB tmpfs at " << dir << " (" << std::strerror(err)
                     << "; needs root): the RLIMIT_FSIZE and /dev/full tests cover the writers";
    }
    struct Unmount {
        fs::path d;
        ~Unmount() {
            ::umount2(d.c_str(), MNT_DETACH);
            std::error_code ec;
            fs::remove_all(d, ec);
        }
    } unmount{dir};

    const ParticleSet ps = particles(20000, 0.0);
    write_checkpoint(dir, ps, state_at(0.0, 0), SimParams{});
    Hdf5Writer w(dir, SimParams{}, "test");
    std::int64_t written = 0;
    std::string msg;
    int err = 0;
    for (int k = 0; k < 10 && msg.empty(); ++k) {
        try {
            w.write(ps, state_at(0.01 * k, k));
            ++written;
        } catch (const WriteError& e) {
            msg = e.what();
            err = e.error_number();
        }
    }
    ASSERT_FALSE(msg.empty()) << "the tmpfs never filled";
    EXPECT_EQ(err, ENOSPC);
    EXPECT_NE(msg.find("No space left on device"), std::string::npos) << msg;
    EXPECT_TRUE(temporaries(dir).empty());
    ASSERT_GE(written, 1);
    EXPECT_EQ(static_cast<std::int64_t>(w.snapshots().size()), written);
    for (std::int64_t k = 0; k < written; ++k) {
        EXPECT_EQ(read_snapshot(dir / snapshot_file_name(k)).particles.x, ps.x) << k;
    }
    EXPECT_EQ(read_checkpoint(dir).particles.x, ps.x);
    // The checkpoint cannot be replaced now either, and the old one stays.
    EXPECT_THROW(write_checkpoint(dir, ps, state_at(1.0, 100), SimParams{}), WriteError);
    EXPECT_EQ(read_checkpoint(dir).state.step, 0);
    EXPECT_TRUE(temporaries(dir).empty());
}
