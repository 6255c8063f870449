// libFuzzer target: the legacy SPHysics case-file reader, then the generator on what it
// accepts (skipped above generate_cap() particles, to keep each input well under a second).
//
// Built a second time as fuzz_planted with SPHJET_FUZZ_PLANTED_CRASH: a heap overflow on
// inputs that start with that word (planted/crash.txt), for the test that the fuzz smoke
// fails on a crashing regression input (smoke.sh goes-red). Never defined in fuzz_legacy.
#include <cstddef>
#include <cstdint>
#include <string_view>
#include <vector>

#include "fuzz_cap.hpp"
#include "fuzz_harness.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
#ifdef SPHJET_FUZZ_PLANTED_CRASH
    if (text.starts_with("SPHJET_FUZZ_PLANTED_CRASH")) {
        const std::vector<char> copy(text.begin(), text.end());
        volatile char past_end = copy.data()[copy.size()];  // one byte past the heap block
        (void)past_end;
    }
#endif
    sphjet::fuzz::guard("legacy", [&] {
        (void)sphjet::fuzz::run_legacy(text, sphjet::fuzz::generate_cap());
    });
    return 0;
}
