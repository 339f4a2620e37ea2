#pragma once

/// \file
/// Will an assembly stand, how can it fall, how far can it be tilted (docs/assemblies.md)? Every
/// decision is exact for the numbers as read: linear programs solved in doubles for guidance,
/// their answers certified in interval arithmetic or found by the exact simplex in rational
/// arithmetic (src/assembly/linear_program.hpp); nothing is decided by a tolerance.

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "momentlab/assembly/assembly.hpp"
#include "momentlab/mechanics/analysis.hpp"

namespace momentlab {

/// Gravity acts on every body at its centre of mass: the body's gravity wrench is
/// (m g, c x m g), exactly as given (decimals as typed: -9.81 is -981/100). The default is
/// (0, -9.81); only its direction matters for every answer here (each condition is homogeneous
/// in it), so any units do.
inline const Rational2 kDefaultGravity = {Rational(), Rational(Dyadic(-981.0), Dyadic(100.0))};

/// One body's motion in a collapse mechanism: its twist (vx, vy, omega) (rounded) and, when it
/// turns, its rotation centre (x, y) = (-vy, vx) / omega.
struct BodyMotion {
    Vec3 twist = Vec3::Zero();
    std::optional<Vec2> rotation_centre;
};

/// Whether an equilibrium exists (every body's gravity wrench plus the contact wrenches on it
/// sum to zero, every contact force in its friction cone, zero allowed), with a certificate
/// either way.
struct Equilibrium {
    bool can_stand = false;
    /// When it can: the contact forces of one equilibrium, per contact the force on body a
    /// (rounded values of an exact equilibrium).
    std::vector<Vec2> forces;
    /// When it cannot: a twist per body that every contact allows (the relative motion at each
    /// contact inside the dual of its friction cone: N . v >= mu |T . v|) and along which
    /// gravity does positive work: the dual of the linear program, a collapse mechanism of limit
    /// analysis (rounded values of an exact certificate).
    std::vector<BodyMotion> mechanism;
};

/// Decides equilibrium under `gravity`. Throws as check_assembly does.
[[nodiscard]] Equilibrium equilibrium(const Assembly& assembly, const Rational2& gravity = kDefaultGravity);

/// An exact direction of the plane, given by its two coordinates scaled so that the larger in
/// magnitude is +-1: each as exact text ("1", "-3/7") and rounded.
struct ExactDirection {
    std::array<std::string, 2> exact;
    Vec2 rounded = Vec2::Zero();
    /// Per coordinate: the rounded value is the exact one (a double).
    std::array<bool, 2> is_double{};
};

/// The gravity vectors for which an equilibrium exists: a closed convex cone of the plane.
struct TiltCone {
    enum class Kind { Empty, Ray, Wedge, HalfPlane, Line, Plane };
    Kind kind = Kind::Empty;
    /// Empty and Plane: none. Ray: [d]. Wedge: [d1, d2], counter-clockwise from d1 to d2 (less
    /// than a half-turn). HalfPlane: [d, -d], the half-plane swept counter-clockwise from d.
    /// Line: [d, -d].
    std::vector<ExactDirection> directions;
};

/// "empty", "ray", "wedge", "halfplane", "line" or "plane".
[[nodiscard]] const char* to_string(TiltCone::Kind kind);

/// The tilting-table test: the cone of gravity vectors for which the assembly can stand. Throws
/// as check_assembly does.
[[nodiscard]] TiltCone tilt_cone(const Assembly& assembly);

/// The contact modes of an assembly under gravity: every mode whose cell of accelerations is
/// non-empty and whose closed sets hold the loads (docs/assemblies.md), and those of them that
/// admit a motion from rest.
struct AssemblyModes {
    /// One letter per contact, in order, of body a's contact point relative to body b's
    /// (s, f, r, l as in docs/design.md); the all-f mode first when listed.
    std::vector<std::string> modes;
    Verdict verdict = Verdict::Inconsistent;
    /// The listed modes whose open cell admits accelerations with the loads balanced: every s
    /// strictly separating, every r / l strictly sliding, some body moving.
    std::vector<std::string> motions;
};

/// Enumerates the modes. Needs every body's inertia. For one body the modes and the verdict are
/// those of query(analyze(scene), gravity wrench). Throws as check_assembly does, and
/// std::invalid_argument for a body without inertia (naming it).
[[nodiscard]] AssemblyModes assembly_modes(const Assembly& assembly, const Rational2& gravity = kDefaultGravity);

/// What a user asks of an assembly at rest under gravity.
enum class Outcome {
    Stands,        ///< an equilibrium, and no motion
    MayFall,       ///< an equilibrium, and motions too (the model allows both)
    Falls,         ///< no equilibrium (and some mode)
    Inconsistent,  ///< no mode at all (Painleve's paradox)
};

/// "stands", "may fall", "falls" or "inconsistent".
[[nodiscard]] const char* to_string(Outcome outcome);

/// The outcome of an equilibrium and the modes.
[[nodiscard]] Outcome outcome_of(const Equilibrium& equilibrium, const AssemblyModes& modes);

/// Options of stand().
struct StandOptions {
    Rational2 gravity = kDefaultGravity;
    /// Also the tilt cone.
    bool tilt = false;
    /// The modes are enumerated up to this many contacts (the search over letter strings can
    /// grow as 4^n); beyond, they are not, and the result says why.
    std::size_t mode_contacts_limit = 16;
};

/// Everything `momentlab stand` answers.
struct StandResult {
    Equilibrium equilibrium;
    /// The modes, the verdict and the motions, when enumerated.
    std::optional<AssemblyModes> modes;
    /// Why the modes were not enumerated (too many contacts, a body without inertia).
    std::string modes_reason;
    /// Needs the modes.
    std::optional<Outcome> outcome;
    std::optional<TiltCone> tilt;
};

/// Equilibrium, modes (when the contacts are few and every body has its inertia), outcome and,
/// when asked, the tilt cone. Throws as check_assembly does.
[[nodiscard]] StandResult stand(const Assembly& assembly, const StandOptions& options = {});

}  // namespace momentlab
