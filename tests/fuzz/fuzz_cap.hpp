// The particle cap of the libFuzzer targets: generate() runs only on accepted cases that
// would make at most this many particles. Default 20000: under ASan a case of 20k particles
// takes about 0.1 s, one of 200k about 1 s, which would cut the executions a hundredfold and
// come close to the 2 s timeout. SPHJET_FUZZ_GENERATE_CAP=200000 raises it.
#pragma once

#include <cstdlib>

namespace sphjet::fuzz {

inline double generate_cap() {
    static const double cap = [] {
        const char* env = std::getenv("SPHJET_FUZZ_GENERATE_CAP");
        const double v = env != nullptr ? std::atof(env) : 0.0;
        return v > 0 ? v : 20000.0;
    }();
    return cap;
}

}  // namespace sphjet::fuzz
