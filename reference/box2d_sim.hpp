#pragma once

// A physical check of momentlab's answers with Box2D (Erin Catto's 2D engine, Debian
// libbox2d-dev), sharing no mechanics with momentlab: the scene's body and obstacles become
// Box2D bodies, an applied force acts on the body from rest, and the contact mode is read off
// the body's velocity after a short time (docs/planning.md, "Checked with Box2D").

#include <string>
#include <vector>

#include "momentlab/mechanics/scene.hpp"

namespace momentlab::physics {

struct SimOptions {
    double hz = 16000.0;          ///< steps per second
    int velocity_iterations = 10;
    int position_iterations = 5;
    /// Seconds from rest: short, so that the body barely moves and its velocity shows the
    /// acceleration at the scene's configuration (momentlab's question).
    double duration = 0.02;
};

/// A constant force, re-applied before every step at the body's material point that starts at
/// `point` (the world direction stays fixed).
struct Action {
    Vec2 force = Vec2::Zero();
    Vec2 point = Vec2::Zero();
};

struct SimResult {
    /// One letter per scene contact, as momentlab's (docs/design.md), read by read_mode.
    std::string mode;
    double angle = 0.0;          ///< the body's rotation at the end (radians)
    /// Per contact: the velocity of its body point along the unit n and t at the end.
    std::vector<Vec2> contact_velocities;
    Vec2 com_velocity = Vec2::Zero();
    double angular_velocity = 0.0;
    /// Box2D's manifold points between the body and the obstacles at the first step.
    std::vector<Vec2> contact_points;
};

/// The mode read from the contact points' velocities (v_n, v_t), one letter per contact, with
/// no wildcard:
///   - every contact f when no contact point moves faster than 0.5% of `free_speed` (|f| / m
///     times the duration: the body stays);
///   - else f when the point moves at under 1% of the fastest contact point (a pivot in Box2D
///     slips by up to about 0.5%);
///   - else s when v_n exceeds (0.5% + 2 |angle|) of its speed: a point sliding along a wall
///     while the body turns leaves the wall at second order (its path is a circle tangent to
///     the wall), by about the angle turned, and that is not a separation at the instant;
///   - else r or l by the sign of v_t.
[[nodiscard]] std::string read_mode(const SimResult& sim, double free_speed);

/// Simulates `scene` (body polygon and obstacles convex, at most 8 vertices; every contact's mu
/// the same) under `action`. Box2D polygons get radius 0, so that the contact surfaces are the
/// scene's (the default skin of b2_polygonRadius would hold the body 2 cm off the wall);
/// sleeping and continuous collision are off; both fixtures get the contacts' mu, so Box2D's sqrt(mu_a mu_b) mixing gives
/// mu. Throws std::invalid_argument for a scene it cannot represent.
[[nodiscard]] SimResult simulate(const Scene& scene, const Action& action, const SimOptions& options = {});

}  // namespace momentlab::physics
