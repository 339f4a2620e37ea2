#include "box2d_sim.hpp"

#include <box2d/box2d.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace momentlab::physics {
namespace {

b2Vec2 to_b2(const Vec2& v) { return b2Vec2(static_cast<float>(v.x()), static_cast<float>(v.y())); }
Vec2 from_b2(const b2Vec2& v) { return Vec2(v.x, v.y); }

b2PolygonShape shape_of(const Polygon& p) {
    if (p.size() < 3 || p.size() > b2_maxPolygonVertices) throw std::invalid_argument("box2d: polygons need 3 to 8 vertices");
    std::vector<b2Vec2> points;
    for (const Vec2& v : p) points.push_back(to_b2(v));
    b2PolygonShape shape;
    shape.Set(points.data(), static_cast<int32>(points.size()));
    if (shape.m_count != static_cast<int32>(p.size())) throw std::invalid_argument("box2d: polygons must be convex");
    shape.m_radius = 0.0f;
    return shape;
}

}  // namespace

std::string read_mode(const SimResult& sim, double free_speed) {
    double fastest = 0;
    for (const Vec2& v : sim.contact_velocities) fastest = std::max(fastest, v.norm());
    std::string letters;
    for (const Vec2& v : sim.contact_velocities) {
        if (fastest < 0.005 * free_speed || v.norm() < 0.01 * fastest) letters += 'f';
        else if (v.x() > (0.005 + 2 * std::abs(sim.angle)) * v.norm()) letters += 's';
        else letters += v.y() > 0 ? 'r' : 'l';
    }
    return letters;
}

SimResult simulate(const Scene& scene, const Action& action, const SimOptions& o) {
    if (!scene.body) throw std::invalid_argument("box2d: the scene needs a body");
    if (scene.contacts.empty()) throw std::invalid_argument("box2d: the scene needs contacts");
    const double mu = scene.contacts.front().mu;
    for (const Contact& c : scene.contacts) {
        if (c.mu != mu || c.mu_kinetic != mu) throw std::invalid_argument("box2d: every contact needs the same mu");
    }
    b2World world(b2Vec2(0.0f, 0.0f));
    world.SetAllowSleeping(false);
    // No continuous collision: the body moves millimetres, so nothing can tunnel, and Box2D
    // 2.4.1's time-of-impact code aborts on an assertion for some resting scenes
    // (b2SeparationFunction::Initialize, "0 < count && count < 3"; found by validate_box2d).
    world.SetContinuousPhysics(false);

    b2BodyDef ground_def;
    b2Body* ground = world.CreateBody(&ground_def);
    for (const Polygon& p : scene.obstacles) {
        const b2PolygonShape shape = shape_of(p);
        b2FixtureDef fd;
        fd.shape = &shape;
        fd.friction = static_cast<float>(mu);
        fd.restitution = 0.0f;
        ground->CreateFixture(&fd);
    }
    b2BodyDef body_def;
    body_def.type = b2_dynamicBody;
    b2Body* body = world.CreateBody(&body_def);
    {
        const b2PolygonShape shape = shape_of(scene.body->polygon);
        b2FixtureDef fd;
        fd.shape = &shape;
        fd.density = 1.0f;
        fd.friction = static_cast<float>(mu);
        fd.restitution = 0.0f;
        body->CreateFixture(&fd);
    }
    const Body& b = scene.body.value();
    b2MassData mass;
    mass.mass = static_cast<float>(b.mass);
    mass.center = to_b2(b.com);
    mass.I = static_cast<float>(b.inertia + b.mass * b.com.squaredNorm());  // about the body origin
    body->SetMassData(&mass);

    SimResult result;
    const b2Vec2 local_point = body->GetLocalPoint(to_b2(action.point));
    const float dt = static_cast<float>(1.0 / o.hz);
    const int steps = static_cast<int>(std::lround(o.duration * o.hz));
    for (int k = 0; k < steps; ++k) {
        body->ApplyForce(to_b2(action.force), body->GetWorldPoint(local_point), true);
        world.Step(dt, o.velocity_iterations, o.position_iterations);
        if (k == 0) {
            for (b2Contact* c = world.GetContactList(); c; c = c->GetNext()) {
                if (!c->IsTouching()) continue;
                b2WorldManifold m;
                c->GetWorldManifold(&m);
                for (int32 i = 0; i < c->GetManifold()->pointCount; ++i) result.contact_points.push_back(from_b2(m.points[i]));
            }
        }
    }
    result.angle = body->GetAngle();
    result.com_velocity = from_b2(body->GetLinearVelocity());
    result.angular_velocity = body->GetAngularVelocity();
    // Velocities of the body points that started at the contacts.
    std::vector<Vec2> velocity;
    double fastest = 0.0;
    for (const Contact& c : scene.contacts) {
        const b2Vec2 world_point = body->GetWorldPoint(to_b2(c.point));
        velocity.push_back(from_b2(body->GetLinearVelocityFromWorldPoint(world_point)));
        fastest = std::max(fastest, velocity.back().norm());
    }
    for (std::size_t j = 0; j < scene.contacts.size(); ++j) {
        const Contact& c = scene.contacts[j];
        const Vec2 n = c.normal.normalized(), t(n.y(), -n.x());
        result.contact_velocities.emplace_back(velocity[j].dot(n), velocity[j].dot(t));
    }
    result.mode = read_mode(result, action.force.norm() / b.mass * o.duration);
    return result;
}

}  // namespace momentlab::physics
