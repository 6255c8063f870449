// libFuzzer target: read_indat on INDAT, IPART, NORMALS.init and gate, split from one input at
// the marker lines "%%IPART%%", "%%NORMALS.init%%" and "%%gate%%" and written to a private
// temporary directory (removed at exit).
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <string_view>
#include <system_error>

#include <unistd.h>

#include "fuzz_harness.hpp"

namespace {

const std::filesystem::path& work_dir() {
    static const std::filesystem::path dir = [] {
        // /dev/shm where there is one: thousands of writes a second, and a disk shared with
        // builds stalls now and then for longer than the 2 s timeout.
        const std::filesystem::path shm = "/dev/shm";
        auto d = (std::filesystem::is_directory(shm) ? shm : std::filesystem::temp_directory_path()) /
                 ("sphjet-fuzz-indat-" + std::to_string(::getpid()));
        std::filesystem::create_directories(d);
        std::atexit([] {
            std::error_code ec;
            std::filesystem::remove_all(work_dir(), ec);
        });
        return d;
    }();
    return dir;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    sphjet::fuzz::guard("indat", [&] { (void)sphjet::fuzz::run_indat(text, work_dir()); });
    return 0;
}
