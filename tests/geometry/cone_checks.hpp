#pragma once

// Comparison of a momentlab Cone with the cddlib oracle's answer for the same input.

#include <algorithm>
#include <sstream>
#include <string>
#include <vector>

#include "../oracle/cdd_oracle.hpp"
#include "momentlab/geometry/cone.hpp"

namespace momentlab::testing {

inline std::string describe(const std::vector<Vec3>& vs) {
    std::ostringstream s;
    s.precision(17);
    s << "{";
    for (const Vec3& v : vs) s << " (" << v.x() << ", " << v.y() << ", " << v.z() << ")";
    s << " }";
    return s.str();
}

using IncidenceSets = std::vector<std::vector<int>>;

// For each functional, the indices of the inputs on which it vanishes (exactly).
template <class F>
IncidenceSets incidences(std::size_t count, const std::vector<Vec3>& inputs, F zero_on) {
    IncidenceSets out;
    for (std::size_t k = 0; k < count; ++k) {
        std::vector<int> s;
        for (std::size_t i = 0; i < inputs.size(); ++i) {
            if (zero_on(k, inputs[i])) s.push_back(static_cast<int>(i));
        }
        out.push_back(s);
    }
    std::sort(out.begin(), out.end());
    return out;
}

/// Empty when `x` (built from `inputs`, generators or half-space normals as `primary` says)
/// has the same dimension, lineality, number of rays and facets as the oracle, the same
/// incidences of its exact representation with the inputs, and contains / satisfies them.
inline std::string compare_with_oracle(const Cone& x, const oracle::OracleCone& o,
                                       const std::vector<Vec3>& inputs, Representation primary) {
    std::ostringstream why;
    if (x.dimension() != o.dimension) why << "dimension " << x.dimension() << " vs oracle " << o.dimension << "; ";
    if (x.lineality_dimension() != o.lineality_dimension) {
        why << "lineality " << x.lineality_dimension() << " vs oracle " << o.lineality_dimension << "; ";
    }
    if (x.rays().size() != o.rays.size()) why << "rays " << x.rays().size() << " vs oracle " << o.rays.size() << "; ";
    if (x.facets().size() != o.facets.size()) {
        why << "facets " << x.facets().size() << " vs oracle " << o.facets.size() << "; ";
    }
    if (!why.str().empty()) return why.str();
    if (primary == Representation::Generators) {
        const auto ours = incidences(x.facets().size(), inputs, [&](std::size_t k, const Vec3& v) {
            return x.facets()[k].dot_sign(v) == Sign::Zero;
        });
        const auto theirs = incidences(o.facets.size(), inputs, [&](std::size_t k, const Vec3& v) {
            return oracle::sign(oracle::dot(o.facets[k], oracle::exact(v))) == 0;
        });
        if (ours != theirs) why << "facet incidences differ; ";
        for (const Vec3& v : inputs) {
            if (!x.has(v)) {
                why << "an input generator is not in the cone; ";
                break;
            }
        }
        // Extreme rays: each of ours lies on the same oracle facets as one of the oracle's rays.
        std::vector<Vec3> ray_values;
        for (const ExactVector& r : x.rays()) ray_values.push_back(r.value());
        const auto ours_r = incidences(o.facets.size(), ray_values, [&](std::size_t k, const Vec3& v) {
            return oracle::sign(oracle::dot(o.facets[k], oracle::exact(v))) == 0;
        });
        IncidenceSets theirs_r;
        for (std::size_t k = 0; k < o.facets.size(); ++k) {
            std::vector<int> s;
            for (std::size_t i = 0; i < o.rays.size(); ++i) {
                if (oracle::sign(oracle::dot(o.facets[k], o.rays[i])) == 0) s.push_back(static_cast<int>(i));
            }
            theirs_r.push_back(s);
        }
        // Compare the number of rays on each facet (ray indices differ between the two).
        auto sizes = [](const IncidenceSets& sets) {
            std::vector<std::size_t> s;
            for (const auto& x2 : sets) s.push_back(x2.size());
            std::sort(s.begin(), s.end());
            return s;
        };
        if (sizes(ours_r) != sizes(theirs_r)) why << "rays per facet differ; ";
    } else {
        const auto ours = incidences(x.rays().size(), inputs, [&](std::size_t k, const Vec3& v) {
            return x.rays()[k].dot_sign(v) == Sign::Zero;
        });
        const auto theirs = incidences(o.rays.size(), inputs, [&](std::size_t k, const Vec3& v) {
            return oracle::sign(oracle::dot(o.rays[k], oracle::exact(v))) == 0;
        });
        if (ours != theirs) why << "ray incidences differ; ";
        for (const ExactVector& r : x.rays()) {
            for (const Vec3& n : inputs) {
                if (r.dot_sign(n) == Sign::Negative) {
                    why << "a ray violates an input half-space; ";
                    break;
                }
            }
        }
    }
    return why.str();
}

}  // namespace momentlab::testing
