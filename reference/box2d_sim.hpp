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
    double hz = 1000.0;           ///< steps per second
    int velocity_iterations = 10;
    int position_iterations = 5;
    /// Seconds from rest: short, so that the body barely moves and its velocity shows the
    /// acceleration at the scene's configuration (momentlab's question).
    double duration = 0.04;
};

/// A constant force, re-applied before every step at the body's material point that starts at
/// `point` (the world direction stays fixed).
struct Action {
    Vec2 force = Vec2::Zero();
    Vec2 point = Vec2::Zero();
};

struct SimResult {
    /// One letter per scene contact, as momentlab's (DESIGN, Conventions), from the velocity of
    /// the body point that started at the contact: s if it leaves along n, r / l if it slides
    /// along +t / -t, f if neither (both below 0.5% of the fastest contact point; all f when
    /// every contact point moves less than 2% of |force| / mass * duration).
    std::string mode;
    double angle = 0.0;          ///< the body's rotation at the end (radians)
    /// Per contact: the velocity of its body point along n and along t at the end.
    std::vector<Vec2> contact_velocities;
    Vec2 com_velocity = Vec2::Zero();
    double angular_velocity = 0.0;
    /// Box2D's manifold points between the body and the obstacles at the first step.
    std::vector<Vec2> contact_points;
};

/// Simulates `scene` (body polygon and obstacles convex, at most 8 vertices; every contact's mu
/// the same) under `action`. Box2D polygons get radius 0, so that the contact surfaces are the
/// scene's (the default skin of b2_polygonRadius would hold the body 2 cm off the wall);
/// sleeping and continuous collision are off; both fixtures get the contacts' mu, so Box2D's sqrt(mu_a mu_b) mixing gives
/// mu. Throws std::invalid_argument for a scene it cannot represent.
[[nodiscard]] SimResult simulate(const Scene& scene, const Action& action, const SimOptions& options = {});

}  // namespace momentlab::physics
