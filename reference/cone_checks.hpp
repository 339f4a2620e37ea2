#pragma once

// Comparison of a momentlab Cone with the cddlib oracle's answer (reference/cdd_oracle): the
// library's exact vectors are converted exactly to rationals and matched one by one with the
// oracle's (extreme rays and facets as directions, lineality and equations as spans).

#include <algorithm>
#include <sstream>
#include <string>
#include <vector>

#include "cdd_oracle.hpp"
#include "exact_scene.hpp"
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

inline std::vector<reference::QVec> exact_list(const std::vector<ExactVector>& vs) {
    std::vector<reference::QVec> out;
    for (const ExactVector& v : vs) out.push_back(reference::to_q(v));
    return out;
}

inline std::vector<reference::QVec> exact_list(const std::vector<Vec3>& vs) {
    std::vector<reference::QVec> out;
    for (const Vec3& v : vs) out.push_back(reference::q(v));
    return out;
}

/// A basis of the span of vs (exact elimination keeps the independent ones, in order).
inline std::vector<reference::QVec> span_basis(const std::vector<reference::QVec>& vs) {
    std::vector<reference::QVec> basis;
    for (const auto& v : vs) {
        std::vector<reference::QVec> trial = basis;
        trial.push_back(v);
        const bool independent = trial.size() == 1 ? !reference::is_zero(v)
                                 : trial.size() == 2 ? !reference::is_zero(reference::cross(trial[0], trial[1]))
                                                     : reference::sign(reference::det(trial[0], trial[1], trial[2])) != 0;
        if (independent) basis = trial;
        if (basis.size() == 3) break;
    }
    return basis;
}

/// v as the functional it defines on span(basis): its values on the basis vectors.
inline std::vector<mpq_class> restricted(const reference::QVec& v, const std::vector<reference::QVec>& basis) {
    std::vector<mpq_class> out;
    for (const auto& b : basis) out.push_back(reference::dot(v, b));
    return out;
}

/// True when a is a positive multiple of b (vectors of equal length).
inline bool same_direction(const std::vector<mpq_class>& a, const std::vector<mpq_class>& b) {
    int k = -1;
    for (std::size_t i = 0; i < a.size(); ++i) {
        if (sgn(a[i]) != sgn(b[i])) return false;
        if (sgn(a[i]) != 0 && k < 0) k = static_cast<int>(i);
    }
    if (k < 0) return false;
    const mpq_class r = a[static_cast<std::size_t>(k)] / b[static_cast<std::size_t>(k)];
    for (std::size_t i = 0; i < a.size(); ++i) {
        if (a[i] != r * b[i]) return false;
    }
    return true;
}

/// True when `ours` and `theirs` are the same directions one to one, each seen as a functional
/// on span(basis): facets are unique only up to the equations (seen on the cone's span), rays
/// up to the lineality (seen on the span of the dual).
inline bool same_directions(const std::vector<reference::QVec>& ours, const std::vector<reference::QVec>& theirs,
                            const std::vector<reference::QVec>& basis) {
    if (ours.size() != theirs.size()) return false;
    std::vector<bool> used(theirs.size(), false);
    for (const auto& v : ours) {
        const auto rv = restricted(v, basis);
        bool found = false;
        for (std::size_t k = 0; k < theirs.size() && !found; ++k) {
            if (!used[k] && same_direction(rv, restricted(theirs[k], basis))) used[k] = found = true;
        }
        if (!found) return false;
    }
    return true;
}

/// `out` followed by each vector of a basis of a space and its negative: the space as a cone.
inline std::vector<reference::QVec> with_spans(std::vector<reference::QVec> out, const std::vector<reference::QVec>& basis) {
    for (const auto& l : basis) {
        out.push_back(l);
        out.push_back(reference::neg(l));
    }
    return out;
}

/// The oracle's generators (rays, then +-lineality) and half-space normals (facets, then
/// +-equations), exactly.
inline std::vector<reference::QVec> oracle_generators(const oracle::OracleCone& o) { return with_spans(o.rays, o.lineality); }
inline std::vector<reference::QVec> oracle_halfspaces(const oracle::OracleCone& o) { return with_spans(o.facets, o.equations); }

/// Empty when `x` equals the oracle's cone exactly: the same dimension and lineality, the same
/// extreme rays and facets (as directions, one to one), the same lineality space and the same
/// space of equations, and its own facet-ray incidences are exact.
inline std::string compare_with_oracle(const Cone& x, const oracle::OracleCone& o) {
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
    const auto rays = exact_list(x.rays()), facets = exact_list(x.facets());
    std::vector<reference::QVec> primal = o.rays, dual = o.facets;
    primal.insert(primal.end(), o.lineality.begin(), o.lineality.end());
    dual.insert(dual.end(), o.equations.begin(), o.equations.end());
    if (!same_directions(rays, o.rays, span_basis(dual))) why << "extreme rays differ; ";
    if (!same_directions(facets, o.facets, span_basis(primal))) why << "facets differ; ";
    if (!oracle::same_span(exact_list(x.lineality()), o.lineality)) why << "lineality spaces differ; ";
    if (!oracle::same_span(exact_list(x.equations()), o.equations)) why << "equations differ; ";
    for (std::size_t j = 0; j < x.facet_rays().size(); ++j) {
        const auto row = x.facet_rays().row(j);
        for (std::size_t i = 0; i < rays.size(); ++i) {
            const bool listed = std::find(row.begin(), row.end(), static_cast<int>(i)) != row.end();
            if (listed != (reference::sign(reference::dot(facets[j], rays[i])) == 0)) {
                why << "facet " << j << " lists the rays on it wrongly; ";
                return why.str();
            }
        }
    }
    return why.str();
}

}  // namespace momentlab::testing
