#pragma once

// Error-free transformations of doubles (Dekker 1971; Shewchuk 1997, section 2), private to the
// core layer. Exact as long as no intermediate overflows or underflows.

namespace momentlab::detail {

// x + y = a + b exactly, with x = fl(a + b) (Knuth's two-sum).
inline void two_sum(double a, double b, double& x, double& y) {
    x = a + b;
    const double b_virtual = x - a;
    const double a_virtual = x - b_virtual;
    y = (a - a_virtual) + (b - b_virtual);
}

}  // namespace momentlab::detail
