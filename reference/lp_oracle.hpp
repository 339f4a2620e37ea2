#pragma once

// A brute-force oracle for contact modes, sharing no code with momentlab's enumeration: for
// each labelling in {s, f, r, l}^n, one exact rational LP (cddlib, GMP) decides whether some
// twist realises it, maximising a slack t <= 1 on the strict inequalities.

#include <set>
#include <string>
#include <vector>

#include "exact_scene.hpp"

namespace momentlab::oracle {

using reference::QMat;
using reference::QVec;

/// True when some twist xi has, for each contact j with letter labels[j]:
/// s: N_j . xi > 0; f: N_j . xi = 0 = T_j . xi; r: N_j . xi = 0 < T_j . xi; l: ... T_j . xi < 0.
/// `labels` may be shorter than the contact list (a prefix).
bool realisable(const std::vector<QVec>& n, const std::vector<QVec>& t, const std::string& labels);

/// Every realisable full labelling, by depth-first search over prefixes (a prefix that is not
/// realisable has no realisable extension), each prefix carried with a twist that realises it
/// (checked exactly), so that the child with that twist's letter needs no LP.
std::set<std::string> all_modes(const std::vector<QVec>& n, const std::vector<QVec>& t);

/// True when the applied wrench e is in the closed set E of the mode `labels`: some twist xi
/// in the closure of the mode's twists and contact forces c_j = sum_k alpha_jk g_jk
/// (alpha >= 0, generators g_jk given per contact for its letter) with M xi = e + sum_j c_j.
bool applied_in_mode(const QMat& m, const std::vector<QVec>& n, const std::vector<QVec>& t,
                     const std::vector<std::vector<QVec>>& contact_generators,
                     const std::string& labels, const QVec& e);

}  // namespace momentlab::oracle
