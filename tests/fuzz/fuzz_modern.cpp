// libFuzzer target: the modern TOML case reader with its override strings (the lines after
// "#%%OVERRIDES%%"), then the generator on what it accepts (skipped above
// generate_cap() particles).
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "fuzz_cap.hpp"
#include "fuzz_harness.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    sphjet::fuzz::guard("modern", [&] {
        (void)sphjet::fuzz::run_modern(text, sphjet::fuzz::generate_cap());
    });
    return 0;
}
