#pragma once

// Membership in a cone by brute force, in exact rationals, sharing nothing with momentlab's
// kernel: by Caratheodory's theorem w is in cone(G) exactly when it is a non-negative
// combination of some linearly independent subset of G (at most three vectors). Every subset
// is tried, so this is for small G (the fuzz targets' inputs).

#include <vector>

#include "exact_scene.hpp"

namespace momentlab::reference {

/// True when w is a non-negative combination of the generators (exact; O(n^3) subsets).
inline bool in_cone(const std::vector<QVec>& g, const QVec& w) {
    if (is_zero(w)) return true;
    const std::size_t n = g.size();
    // One generator: w = a g, a >= 0.
    for (std::size_t i = 0; i < n; ++i) {
        if (!is_zero(g[i]) && is_zero(cross(g[i], w)) && sign(dot(g[i], w)) > 0) return true;
    }
    // Two independent generators spanning a plane holding w: w = a g_i + b g_j.
    for (std::size_t i = 0; i < n; ++i) {
        for (std::size_t j = i + 1; j < n; ++j) {
            const QVec c = cross(g[i], g[j]);
            if (is_zero(c) || sign(dot(c, w)) != 0) continue;
            // a = (w x g_j) . c / |c|^2, b = (g_i x w) . c / |c|^2: signs of the numerators.
            if (sign(dot(cross(w, g[j]), c)) >= 0 && sign(dot(cross(g[i], w), c)) >= 0) return true;
        }
    }
    // Three independent generators: Cramer's rule, signs of the determinants.
    for (std::size_t i = 0; i < n; ++i) {
        for (std::size_t j = i + 1; j < n; ++j) {
            for (std::size_t k = j + 1; k < n; ++k) {
                const int d = sign(det(g[i], g[j], g[k]));
                if (d == 0) continue;
                if (sign(det(w, g[j], g[k])) * d >= 0 && sign(det(g[i], w, g[k])) * d >= 0 &&
                    sign(det(g[i], g[j], w)) * d >= 0) {
                    return true;
                }
            }
        }
    }
    return false;
}

}  // namespace momentlab::reference
