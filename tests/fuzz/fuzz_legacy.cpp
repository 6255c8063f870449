// libFuzzer target: the legacy SPHysics case-file reader, then the generator on what it
// accepts (skipped above generate_cap() particles, to keep each input well under a second).
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "fuzz_cap.hpp"
#include "fuzz_harness.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    sphjet::fuzz::guard("legacy", [&] {
        (void)sphjet::fuzz::run_legacy(text, sphjet::fuzz::generate_cap());
    });
    return 0;
}
