// sphjet: the command-line program. Sub-commands register themselves (cli/commands.hpp).
#include <unistd.h>
#ifdef __GLIBC__
#include <malloc.h>
#endif

#include <cstdlib>
#include <exception>
#include <iostream>

#include <CLI/CLI.hpp>

#include "cli/commands.hpp"
#include "io/h5_util.hpp"

namespace {

// How OpenMP threads wait at a barrier. A step has about a dozen barriers, so this decides how
// fast two threads run. libgomp's default spins for about 3 ms before it sleeps, which loses
// badly when the machine is shared (a 2-core CI runner running two tests at once slowed down
// six-fold in our measurements); sleeping at once (OMP_WAIT_POLICY=PASSIVE) costs a futex sleep
// and wake-up per barrier: Case1 on two threads of a quiet machine ran at 3.1e6 particle-steps/s
// so, and at 3.8e6 when the waiters first spin 5000 rounds (GOMP_SPINCOUNT, tens of
// microseconds) and then sleep, with no more cpu time; two such runs sharing two cores lose
// 1.35x to sleeping at once (README, Performance). So the default is the short spin; the test
// suite, whose tests run side by side, asks for PASSIVE (tests/CMakeLists.txt). libgomp reads
// both variables when it is loaded, before main, so the program re-executes itself once with
// them set, unless the user chose either.
void prefer_short_openmp_spins(char** argv) {
    if (std::getenv("OMP_WAIT_POLICY") != nullptr || std::getenv("GOMP_SPINCOUNT") != nullptr)
        return;
    if (setenv("OMP_WAIT_POLICY", "PASSIVE", 1) != 0) return;
    if (setenv("GOMP_SPINCOUNT", "5000", 1) != 0) return;
    execv("/proc/self/exe", argv);  // returns only on failure: then run as we are
}

// The core allocates some work arrays per force evaluation (the surface-tension passes, the
// axisymmetric sums, the axis images). glibc gives freed memory at the top of the heap back
// to the system beyond 128 KiB and serves blocks over 128 KiB (adaptively more) by mmap, so
// those arrays came back as fresh pages every evaluation: page faults and brk calls took
// about 8% of an axisymmetric jet's time (perf). Freed memory stays in the process instead.
// One heap for all threads: with one per thread (glibc's default) a block freed by one thread
// is not reused by another, and the neighbour lists' rows are reallocated by whichever thread
// builds them; the 1e6-particle dam break on two threads then peaked at 775-965 MB from run to
// run of the same command, and at 742 MB in every run with one heap, at the same speed
// (docs/performance.md, "One heap", 4005352). The core allocates outside its pair loops only.
void keep_freed_memory() {
#ifdef __GLIBC__
    mallopt(M_TRIM_THRESHOLD, 1 << 30);
    mallopt(M_MMAP_THRESHOLD, 32 << 20);  // glibc's largest on 64-bit systems
    mallopt(M_ARENA_MAX, 1);
#endif
}

}  // namespace

int main(int argc, char** argv) {
    prefer_short_openmp_spins(argv);
    keep_freed_memory();
    CLI::App app{"sphjet: 2D weakly compressible SPH (a modern fork of SPHysics 2D) with CSF "
                 "surface tension"};
    app.set_version_flag("--version", std::string(SPHJET_VERSION) + " (" + sphjet::h5::git_hash() +
                                          ", core built for " SPHJET_ARCH ")");
    app.require_subcommand(1);
    sphjet::cli::set_command_line(argc, argv);
    sphjet::cli::register_run(app);
    sphjet::cli::register_gen(app);
    sphjet::cli::register_bench(app);
    sphjet::cli::register_compare(app);
    sphjet::cli::register_analyse(app);
    sphjet::cli::register_convert(app);
    sphjet::cli::register_drop(app);
    sphjet::cli::register_keys(app);
    sphjet::cli::register_modes(app);
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return app.exit(e);
    } catch (const std::exception& e) {
        std::cerr << "sphjet: error: " << e.what() << "\n";
        return 1;
    }
    return 0;
}
