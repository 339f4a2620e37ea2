#pragma once

/// \file
/// The body-at-rest problem as the standard acceleration-level planar Coulomb LCP, solved by
/// Siconos Numerics (Lemke, and enumeration of every complementary basis). This is the
/// independent check of `query`: nothing here uses momentlab's cones or modes. The
/// formulation is written out in docs/validation.md, "The LCP".

#include <Eigen/Dense>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "momentlab/mechanics/scene.hpp"

namespace momentlab::validation {

/// One solution of the LCP: z = (lambda_n, lambda_+, lambda_-, sigma) and w = M z + q, each
/// of 4n entries, contact by contact in blocks of n.
struct LcpSolution {
    Eigen::VectorXd z, w;
    /// Siconos' index of the complementary basis (enumeration only; -1 for Lemke).
    std::int64_t basis = -1;
};

/// What the enumeration found.
struct LcpEnumeration {
    std::vector<LcpSolution> solutions;  ///< one per basis that solves the LCP
    int counted = 0;                     ///< solutions counted by one pass in multiple-solutions mode
    std::uint64_t bases = 0;             ///< complementary bases tried: 2^(4n) per pass
};

/// The LCP of a scene's body at rest. Friction is the static mu of each contact on sliding
/// too (an LCP has one coefficient), so scenes compared with momentlab set mu_kinetic = mu.
class CoulombLcp {
public:
    /// Throws std::invalid_argument when the scene has no body or no contacts.
    explicit CoulombLcp(const Scene& scene);
    ~CoulombLcp();
    CoulombLcp(const CoulombLcp&) = delete;
    CoulombLcp& operator=(const CoulombLcp&) = delete;

    /// Assembles the LCP of another scene, reusing the buffers and solver options when the
    /// number of contacts is the same (as a simulator would, step after step). Throws as the
    /// constructor does.
    void reset(const Scene& scene);

    /// 4n.
    [[nodiscard]] int size() const { return size_; }

    /// Lexicographic Lemke (Siconos lcp_lexicolemke) for the applied wrench e: the solution, or
    /// false when Lemke stops without one (a secondary ray: the LCP may have no solution).
    bool lemke(const Vec3& e, LcpSolution& out) { return pivot(e, out, false); }

    /// Lemke's rule through Siconos' general pivoting code (lcp_pivot with
    /// SICONOS_LCP_PIVOT_LEMKE), which has pivot tolerances: the same contract as lemke().
    bool lemke_pivot(const Vec3& e, LcpSolution& out) { return pivot(e, out, true); }

    /// Siconos lcp_enum: one pass in multiple-solutions mode (the count), then every solution,
    /// resuming the enumeration after each one (SICONOS_LCP_IPARAM_ENUM_SEED). `tolerance` is
    /// lcp_enum's: basic variables >= -tolerance count as non-negative.
    LcpEnumeration enumerate(const Vec3& e, double tolerance = 1e-10);

    /// The acceleration twist M^-1 (e + sum_j lambda_nj N_j + (lambda_+j - lambda_-j) T_j).
    [[nodiscard]] Vec3 acceleration(const Vec3& e, const LcpSolution& s) const;

    /// The contact mode of a solution read from its twist: per contact 's' when N_j . a > tol,
    /// else 'r' / 'l' when T_j . a > tol / < -tol, else 'f'. `tol` is relative to the scale of
    /// the terms: the largest of 1, |q| and |z| max|M_ij|.
    [[nodiscard]] std::string mode(const Vec3& e, const LcpSolution& s, double tol = 1e-9) const;

    /// The largest violation of z >= 0, w >= 0, z . w = 0 (entrywise) and w = M z + q,
    /// divided by 1 + max|q|: absolute, because a near-singular basis gives "solutions" with
    /// entries near 1e16 whose relative error is small and which solve nothing.
    [[nodiscard]] double residual(const Vec3& e, const LcpSolution& s) const;

    /// Whether a solution solves the LCP: residual <= 1e-8.
    [[nodiscard]] bool solves(const Vec3& e, const LcpSolution& s) const { return residual(e, s) <= 1e-8; }

private:
    struct Siconos;
    void set_wrench(const Vec3& e);
    // Lemke's method: lcp_lexicolemke, or lcp_pivot with Lemke's rule when `general`.
    bool pivot(const Vec3& e, LcpSolution& out, bool general);

    int contacts_ = 0;
    int size_ = 0;
    Eigen::Matrix3d minv_;
    Eigen::MatrixXd d_;  // 3 x 3n: N_j, T_j, -T_j
    Eigen::MatrixXd m_;  // the LCP matrix
    Eigen::VectorXd q_;
    std::unique_ptr<Siconos> siconos_;
};

}  // namespace momentlab::validation
