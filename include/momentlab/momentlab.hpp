#pragma once

/// \file
/// momentlab: exact planar contact mechanics with Coulomb friction by Mason's graphical methods
/// (moment labels for sets of forces, rotation centres for motions; Mason 1991). This header is
/// the front door: it gives the whole public API, and reads as the pipeline a program follows.
///
///   1. A scene: `read_scene_text` / `read_scene` (io/scene_json.hpp) or a `Scene` built by hand
///      (mechanics/scene.hpp): a body (mass, centre of mass, inertia, outline), its point
///      `Contact`s (point, inward normal of any length, mu, mu_kinetic) and fixed obstacles.
///   2. Contacts from geometry: `find_contacts` (mechanics/find_contacts.hpp), when the scene
///      gives polygons instead of contacts.
///   3. Modes: `enumerate_modes` (mechanics/modes.hpp) lists every contact mode, letters s, f,
///      r, l per contact (`Mode::letters`), with its set of twists and `rotation_centres`.
///   4. Per-mode sets: `analyze` (mechanics/analysis.hpp) gives, per mode, the cones F (total
///      wrenches), T (contact wrenches) and E (applied wrenches) as `ModeForces`.
///   5. Questions: `query(scene, e)` (mechanics/analysis.hpp) gives the modes an applied wrench e
///      produces (`.letters`, sorted; `.verdict`: unique, ambiguous, inconsistent), the fast way
///      (certified doubles for 2 to 12 contacts, the exact walk where they cannot decide);
///      `QueryIndex(scene)` (mechanics/query_index.hpp) answers millions of them on one scene.
///      Other paths and each answer's diagnostics are in mechanics/advanced.hpp.
///   5b. Grasp closure: `closure` (mechanics/closure.hpp): form and force closure, exactly, with
///      a certificate either way.
///   6. Plans (planning/): `plan_tilt`, `plan_push`, `plan_comply`: the actions W whose
///      W ∩ E_goal reaches a goal mode (Mason 1991, section 3).
///   7. Pictures (render/): figures of labels, modes and plans as SVG, PDF or PNG.
///
/// A front end (CLI, Python, web) poses these through the application layer, `Problem`
/// (app/problem.hpp), where the checks of what a user gives and their messages live once.
///
/// Underneath: `Cone` (geometry/cone.hpp), a closed polyhedral cone of wrenches or twists in
/// both representations; `Labels` (geometry/labels.hpp), its moment labels; the force sets of
/// the paper's Figure 1 (geometry/force_sets.hpp); and exact arithmetic (core/): every
/// decision is the exact sign of a polynomial in the input doubles (`Dyadic`, `ExactVector`).
/// Conventions (signs, units, mode letters) are in docs/design.md.

#include "momentlab/app/checks.hpp"
#include "momentlab/app/problem.hpp"
#include "momentlab/core/dyadic.hpp"
#include "momentlab/core/exact.hpp"
#include "momentlab/core/predicates.hpp"
#include "momentlab/core/sign.hpp"
#include "momentlab/core/vec.hpp"
#include "momentlab/geometry/cone.hpp"
#include "momentlab/geometry/force_sets.hpp"
#include "momentlab/geometry/labels.hpp"
#include "momentlab/geometry/polygon.hpp"
#include "momentlab/io/files.hpp"
#include "momentlab/io/force_set_json.hpp"
#include "momentlab/io/input_error.hpp"
#include "momentlab/io/json_output.hpp"
#include "momentlab/io/json_writer.hpp"
#include "momentlab/io/scene_json.hpp"
#include "momentlab/mechanics/analysis.hpp"
#include "momentlab/mechanics/closure.hpp"
#include "momentlab/mechanics/margin.hpp"
#include "momentlab/mechanics/query_index.hpp"
#include "momentlab/mechanics/find_contacts.hpp"
#include "momentlab/mechanics/modes.hpp"
#include "momentlab/mechanics/scene.hpp"
#include "momentlab/planning/comply.hpp"
#include "momentlab/planning/directions.hpp"
#include "momentlab/planning/fixed_wrench.hpp"
#include "momentlab/planning/push.hpp"
#include "momentlab/planning/tilt.hpp"
#include "momentlab/planning/unique.hpp"
#include "momentlab/render/figure.hpp"
#include "momentlab/render/pictures.hpp"
