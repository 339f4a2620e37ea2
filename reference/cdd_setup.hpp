#pragma once
// cddlib's global constants, set once for every oracle that calls cddlib (cdd_oracle, lp_oracle).
#include <setoper.h>
#include <cdd.h>

#include <mutex>

namespace momentlab::oracle {

inline void cdd_setup() {
    static std::once_flag once;
    std::call_once(once, [] { dd_set_global_constants(); });
}

}  // namespace momentlab::oracle
