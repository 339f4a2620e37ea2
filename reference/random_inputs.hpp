#pragma once

// Seeded random inputs for property tests: our own mapping from std::mt19937_64 to values
// (the std distributions differ between standard libraries).

#include <cstdint>
#include <random>
#include <vector>

#include "momentlab/core/vec.hpp"

namespace momentlab::testing {

class Random {
public:
    explicit Random(std::uint64_t seed) : rng_(seed) {}
    /// Uniform in [0, 1) with 53 random bits.
    double unit() { return static_cast<double>(rng_() >> 11) * 0x1p-53; }
    /// Uniform in [lo, hi).
    double uniform(double lo, double hi) { return lo + (hi - lo) * unit(); }
    /// Uniform integer in [lo, hi].
    int integer(int lo, int hi) {
        return lo + static_cast<int>(rng_() % static_cast<std::uint64_t>(hi - lo + 1));
    }
    Vec3 vec3(double r) { return Vec3(uniform(-r, r), uniform(-r, r), uniform(-r, r)); }
    Vec3 int_vec3(int r) { return Vec3(integer(-r, r), integer(-r, r), integer(-r, r)); }

private:
    std::mt19937_64 rng_;
};

/// The families of generator sets used by the cone property tests.
enum class Family { GeneralDoubles, HalfSpaceDoubles, SmallIntegers, Coplanar, Collinear,
                    Antipodal, PureMoments, Mixed };

inline const char* family_name(Family f) {
    switch (f) {
        case Family::GeneralDoubles: return "general doubles";
        case Family::HalfSpaceDoubles: return "doubles in a half-space";
        case Family::SmallIntegers: return "small integers";
        case Family::Coplanar: return "coplanar integers";
        case Family::Collinear: return "collinear integers";
        case Family::Antipodal: return "antipodal pairs";
        case Family::PureMoments: return "pure moments and forces";
        default: return "mixed degenerate";
    }
}

/// Whether the family has exactly degenerate (small-integer) coordinates.
inline bool is_integral(Family f) {
    return f != Family::GeneralDoubles && f != Family::HalfSpaceDoubles;
}

/// A random generator set of the family, with 1 .. max_n vectors.
inline std::vector<Vec3> random_generators(Random& rnd, Family family, int max_n) {
    const int n = rnd.integer(1, max_n);
    std::vector<Vec3> g;
    switch (family) {
        case Family::GeneralDoubles:
            for (int i = 0; i < n; ++i) g.push_back(rnd.vec3(1.0));
            break;
        case Family::HalfSpaceDoubles:
            for (int i = 0; i < n; ++i) g.push_back(Vec3(rnd.uniform(-1, 1), rnd.uniform(-1, 1), rnd.uniform(0.05, 1)));
            break;
        case Family::SmallIntegers:
            for (int i = 0; i < n; ++i) g.push_back(rnd.int_vec3(2));
            break;
        case Family::Coplanar: {
            const Vec3 a = rnd.int_vec3(2), b = rnd.int_vec3(2);
            for (int i = 0; i < n; ++i) g.push_back(rnd.integer(-2, 2) * a + rnd.integer(-2, 2) * b);
            break;
        }
        case Family::Collinear: {
            const Vec3 a = rnd.int_vec3(3);
            for (int i = 0; i < n; ++i) g.push_back(rnd.integer(-3, 3) * a);
            if (rnd.integer(0, 1)) g.push_back(rnd.int_vec3(2));
            break;
        }
        case Family::Antipodal:
            for (int i = 0; i < n; ++i) {
                const Vec3 a = rnd.int_vec3(2);
                g.push_back(a);
                if (rnd.integer(0, 2) == 0) g.push_back(-rnd.integer(1, 3) * a);
            }
            break;
        case Family::PureMoments:
            for (int i = 0; i < n; ++i) {
                const int k = rnd.integer(0, 3);
                if (k == 0) g.push_back(Vec3(0, 0, rnd.integer(-2, 2)));
                else if (k == 1) g.push_back(Vec3(rnd.integer(-2, 2), rnd.integer(-2, 2), 0));
                else g.push_back(rnd.int_vec3(1));
            }
            break;
        case Family::Mixed:
            for (int i = 0; i < n; ++i) {
                const Vec3 a = rnd.int_vec3(2);
                g.push_back(a);
                const int k = rnd.integer(0, 3);
                if (k == 0) g.push_back(a);                         // repeated
                if (k == 1) g.push_back(2.0 * a);                   // collinear
                if (k == 2 && i > 0) g.push_back(a + g[g.size() - 2]);  // coplanar with neighbours
            }
            break;
    }
    return g;
}

}  // namespace momentlab::testing
