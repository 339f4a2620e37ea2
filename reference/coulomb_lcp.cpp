#include "coulomb_lcp.hpp"

#include <siconos/numerics/LCP_Solvers.h>
#include <siconos/numerics/LinearComplementarityProblem.h>
#include <siconos/numerics/NumericsMatrix.h>
#include <siconos/numerics/SolverOptions.h>
#include <siconos/numerics/lcp_cst.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>


namespace momentlab::validation {

// The Siconos objects: the matrix (column-major, dense), the problem and one set of options
// per solver. q points into CoulombLcp::q_.
struct CoulombLcp::Siconos {
    NumericsMatrix* matrix = nullptr;
    LinearComplementarityProblem problem{};
    SolverOptions* lemke = nullptr;
    SolverOptions* pivot = nullptr;
    SolverOptions* enumeration = nullptr;

    ~Siconos() {
        if (enumeration != nullptr) {
            if (matrix != nullptr) lcp_enum_reset(&problem, enumeration, 1);  // initialised with the matrix
            solver_options_delete(enumeration);
        }
        if (lemke != nullptr) solver_options_delete(lemke);
        if (pivot != nullptr) solver_options_delete(pivot);
        if (matrix != nullptr) NM_free(matrix);  // NM_clear, then free
    }
};

CoulombLcp::CoulombLcp(const Scene& scene) : siconos_(std::make_unique<Siconos>()) {
    Siconos& s = *siconos_;
    s.lemke = solver_options_create(SICONOS_LCP_LEMKE);
    s.pivot = solver_options_create(SICONOS_LCP_PIVOT);
    s.pivot->iparam[SICONOS_LCP_IPARAM_PIVOTING_METHOD_TYPE] = SICONOS_LCP_PIVOT_LEMKE;
    s.enumeration = solver_options_create(SICONOS_LCP_ENUM);
    reset(scene);
}

void CoulombLcp::reset(const Scene& scene) {
    if (!scene.body) throw std::invalid_argument("the LCP needs the body's mass and inertia");
    if (scene.contacts.empty()) throw std::invalid_argument("the LCP needs at least one contact");
    const int n = static_cast<int>(scene.contacts.size());
    const bool resized = 4 * n != size_;
    contacts_ = n;
    size_ = 4 * n;
    // The LCP's own matrices, in doubles, from the scene's raw numbers (nothing of momentlab's).
    const Body& b = *scene.body;
    const double m = b.mass, cx = b.com.x(), cy = b.com.y();
    const double inertia = b.radius_of_gyration ? m * *b.radius_of_gyration * *b.radius_of_gyration : b.inertia;
    Eigen::Matrix3d mass;
    mass << m, 0.0, -m * cy, 0.0, m, m * cx, -m * cy, m * cx, inertia + m * (cx * cx + cy * cy);
    minv_ = mass.inverse();
    d_.resize(3, 3 * n);  // no allocation when the size is the same
    for (int j = 0; j < n; ++j) {
        const Contact& c = scene.contacts[static_cast<std::size_t>(j)];
        const Vec2 p = c.point, nv = c.normal, t(nv.y(), -nv.x());
        d_.col(j) = Vec3(nv.x(), nv.y(), p.x() * nv.y() - p.y() * nv.x());
        d_.col(n + j) = Vec3(t.x(), t.y(), p.x() * t.y() - p.y() * t.x());
        d_.col(2 * n + j) = -d_.col(n + j);
    }
    // w_n = N'a, w_+ = sigma + T'a, w_- = sigma - T'a, w_s = mu lambda_n - lambda_+ - lambda_-,
    // with a = M^-1 (e + D lambda).
    m_.setZero(size_, size_);
    m_.topLeftCorner(3 * n, 3 * n).noalias() = d_.transpose() * (minv_ * d_);
    for (int j = 0; j < n; ++j) {
        m_(n + j, 3 * n + j) = 1;
        m_(2 * n + j, 3 * n + j) = 1;
        m_(3 * n + j, j) = scene.contacts[static_cast<std::size_t>(j)].mu;
        m_(3 * n + j, n + j) = -1;
        m_(3 * n + j, 2 * n + j) = -1;
    }
    q_.setZero(size_);

    Siconos& s = *siconos_;
    if (resized) {
        if (s.matrix != nullptr) {
            lcp_enum_reset(&s.problem, s.enumeration, 1);
            NM_free(s.matrix);
        }
        s.matrix = NM_create(NM_DENSE, size_, size_);
    }
    std::copy(m_.data(), m_.data() + m_.size(), s.matrix->matrix0);  // both column-major
    s.problem = LinearComplementarityProblem{size_, s.matrix, q_.data()};
    if (resized) lcp_enum_init(&s.problem, s.enumeration, 1);
}

CoulombLcp::~CoulombLcp() = default;

void CoulombLcp::set_wrench(const Vec3& e) {
    q_.head(3 * contacts_) = d_.transpose() * (minv_ * e);
}

bool CoulombLcp::pivot(const Vec3& e, LcpSolution& out, bool general) {
    set_wrench(e);
    out.z.setZero(size_);  // no allocation when reused
    out.w.setZero(size_);
    out.basis = -1;
    int info = 0;
    Siconos& s = *siconos_;
    if (general) lcp_pivot(&s.problem, out.z.data(), out.w.data(), &info, s.pivot);
    else lcp_lexicolemke(&s.problem, out.z.data(), out.w.data(), &info, s.lemke);
    return info == 0;
}

LcpEnumeration CoulombLcp::enumerate(const Vec3& e, double tolerance) {
    set_wrench(e);
    SolverOptions* o = siconos_->enumeration;
    o->dparam[SICONOS_DPARAM_TOL] = tolerance;
    const std::uint64_t cases = std::uint64_t{1} << size_;
    LcpEnumeration out;
    Eigen::VectorXd z = Eigen::VectorXd::Zero(size_), w = z;
    int info = 0;

    // One pass in multiple-solutions mode: it counts every solving basis (and keeps the last).
    o->iparam[SICONOS_LCP_IPARAM_ENUM_MULTIPLE_SOLUTIONS] = 1;
    o->iparam[SICONOS_LCP_IPARAM_ENUM_SEED] = 0;
    o->iparam[SICONOS_LCP_IPARAM_ENUM_NUMBER_OF_SOLUTIONS] = 0;
    lcp_enum(&siconos_->problem, z.data(), w.data(), &info, o);
    out.counted = o->iparam[SICONOS_LCP_IPARAM_ENUM_NUMBER_OF_SOLUTIONS];
    out.bases += cases;

    // Then each solution: stop at the first solving basis, resume after it. The enumeration
    // wraps around to basis 0, so a basis below the seed means every solution has been seen.
    o->iparam[SICONOS_LCP_IPARAM_ENUM_MULTIPLE_SOLUTIONS] = 0;
    std::uint64_t seed = 0;
    while (seed < cases && static_cast<int>(out.solutions.size()) < out.counted) {
        o->iparam[SICONOS_LCP_IPARAM_ENUM_SEED] = static_cast<int>(seed);
        lcp_enum(&siconos_->problem, z.data(), w.data(), &info, o);
        if (info != 0) break;
        const auto basis = static_cast<std::uint64_t>(o->iparam[SICONOS_LCP_IPARAM_ENUM_CURRENT_ENUM]);
        if (basis < seed) break;
        out.bases += basis - seed + 1;
        out.solutions.push_back(LcpSolution{z, w, static_cast<std::int64_t>(basis)});
        seed = basis + 1;
    }
    return out;
}

Vec3 CoulombLcp::acceleration(const Vec3& e, const LcpSolution& s) const {
    return minv_ * (e + d_ * s.z.head(3 * contacts_));
}

std::string CoulombLcp::mode(const Vec3& e, const LcpSolution& s, double tol) const {
    const Vec3 a = acceleration(e, s);
    const int n = contacts_;
    // The scale of the terms a velocity is computed from: with large contact forces (a squeeze)
    // Lemke's rounding leaves velocities of 1e-9 where the exact solution has 0.
    const double scale = std::max({1.0, (d_.transpose() * (minv_ * e)).cwiseAbs().maxCoeff(),
                                   s.z.cwiseAbs().maxCoeff() * m_.cwiseAbs().maxCoeff()});
    const double t = tol * scale;
    std::string letters;
    for (int j = 0; j < n; ++j) {
        const double normal = d_.col(j).dot(a), tangential = d_.col(n + j).dot(a);
        if (normal > t) letters += 's';
        else if (tangential > t) letters += 'r';
        else if (tangential < -t) letters += 'l';
        else letters += 'f';
    }
    return letters;
}

double CoulombLcp::residual(const Vec3& e, const LcpSolution& s) const {
    Eigen::VectorXd q = Eigen::VectorXd::Zero(size_);
    q.head(3 * contacts_) = d_.transpose() * (minv_ * e);
    const Eigen::VectorXd w = m_ * s.z + q;
    double r = (w - s.w).cwiseAbs().maxCoeff();
    for (int k = 0; k < size_; ++k) {
        r = std::max({r, -s.z(k), -s.w(k), std::abs(s.z(k) * s.w(k))});
    }
    return r / (1.0 + q.cwiseAbs().maxCoeff());
}

}  // namespace momentlab::validation
