#pragma once

/// \file
/// Contact modes of a body at rest (docs/design.md, "Contact modes"): the relatively open faces of the
/// cone A of feasible twists, refined by the sign of the tangential velocity at the contacts
/// that stay closed. Letters per contact, in input order: s separating, f fixed, r sliding
/// with t . v > 0, l sliding with t . v < 0.

#include <iosfwd>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "momentlab/geometry/cone.hpp"
#include "momentlab/geometry/labels.hpp"
#include "momentlab/mechanics/scene.hpp"

namespace momentlab {

/// Told how long work goes: `what` is being done, `done` of `total` units (called often, from the
/// working thread; may be empty). The command line draws it on a terminal (docs/architecture.md).
using Progress = std::function<void(std::string_view what, std::size_t done, std::size_t total)>;

/// What one contact does in a mode, with its letter (docs/design.md, Conventions): it separates
/// (the paper's parting), stays fixed (rolls or sticks), or slides with t . v > 0 (r) or
/// t . v < 0 (l), t = (n.y, -n.x).
enum class ContactMode : char { Separating = 's', Fixed = 'f', SlidingRight = 'r', SlidingLeft = 'l' };

/// The letter of a contact mode.
[[nodiscard]] constexpr char letter(ContactMode m) { return static_cast<char>(m); }
/// Coulomb's rule for a sliding contact (Mason 1991, section 2.1; docs/design.md, Conventions):
/// friction opposes the slip, so the contact force lies along the friction edge n + s mu_k t with
/// s = -1 for r (sliding along +t) and s = +1 for l; 0 for s and f, which have no one edge. The
/// one place the rule is written (tools/house_checks.sh).
[[nodiscard]] constexpr int opposing_friction(ContactMode m) {
    return m == ContactMode::SlidingRight ? -1 : (m == ContactMode::SlidingLeft ? 1 : 0);
}
/// The contact mode of a letter s, f, r or l; throws std::invalid_argument for another one.
[[nodiscard]] ContactMode contact_mode(char letter);
/// "separates", "fixed", "slides along +t" or "slides along -t".
[[nodiscard]] const char* describe(ContactMode m);
/// Writes the letter.
std::ostream& operator<<(std::ostream& out, ContactMode m);

/// One contact mode.
struct Mode {
    /// One letter per contact: 's', 'f', 'r' or 'l' (ContactMode).
    std::string letters;
    /// The closure of the mode's twists (velocities, or accelerations at rest), exact.
    Cone twists;
    /// What contact j does.
    [[nodiscard]] ContactMode at(std::size_t j) const { return contact_mode(letters.at(j)); }
};

/// Every kinematically feasible mode of a scene.
struct ModeSet {
    /// A = {xi : N_j . xi >= 0 for every contact j}.
    Cone feasible_twists;
    /// The all-f mode first (always feasible), then the others; each exactly once.
    std::vector<Mode> modes;
};

/// The rotation centres of a mode, labelled as in Reuleaux's method: the + region holds the
/// centres of its counter-clockwise twists, the - region those of its clockwise ones
/// (a twist omega (y, -x, 1) rotates about (x, y)); translations are the directions at
/// infinity. These are the moment labels of the dual of the twist cone.
[[nodiscard]] Labels rotation_centres(const Mode& mode);

/// Enumerates the contact modes exactly: every decision is the exact sign of a polynomial in
/// the stored N_j = (n_j, p_j x n_j) and T_j = (t_j, p_j x t_j). O(n log n + M n) time and
/// O(n + M n) memory for n contacts and M modes (the letters alone are M n; docs/benchmarks.md,
/// "Nearly degenerate scenes").
/// Throws std::invalid_argument for a contact with a non-finite point, a zero or non-finite
/// normal, or a negative or non-finite mu / mu_kinetic (as Contact::make would).
[[nodiscard]] ModeSet enumerate_modes(const std::vector<Contact>& contacts, const Progress& progress = nullptr);

}  // namespace momentlab
