// Grasp closure (mechanics/closure.hpp), against hand derivations on the bundled grasps and an
// exact LP on random ones: the contacts' wrenches positively span R^3 exactly when each of the
// six wrenches +-e_k is a non-negative combination of them (reference/lp_oracle, exact rationals
// from the scene's raw numbers). Certificates are checked from the raw numbers too, and the
// quality of every grasp that holds against its definition computed here (the facets of the hull
// of the unit wrenches by cddlib).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "../common/examples.hpp"
#include "../common/scenes.hpp"
#include "../common/sizes.hpp"
#include "cdd_oracle.hpp"
#include "mode_oracle.hpp"
#include "random_inputs.hpp"
#include "momentlab/mechanics/closure.hpp"

namespace momentlab {
namespace {

using reference::QVec;

// The contacts' generators from the raw numbers: N_j (form) or the friction edges (force).
std::vector<QVec> raw_generators(const Scene& scene, bool force) {
    std::vector<QVec> out;
    for (const Contact& c : scene.contacts) {
        const reference::QContact q(c);
        if (force) {
            for (const QVec& g : q.generators('f')) out.push_back(g);
        } else {
            out.push_back(q.normal());
        }
    }
    return out;
}

// R^3 = cone(G) iff each +-e_k is in it: e = M xi - c with M = 0 and c in cone(G) (the LP of the
// per-mode oracle with every contact separating, so that xi = 0 is allowed).
bool oracle_spans(const Scene& scene, bool force) {
    const testing::ExactContacts c(scene.contacts);
    const std::vector<QVec> g = raw_generators(scene, force);
    const QVec zero{0, 0, 0};
    for (int k = 0; k < 3; ++k) {
        for (int s : {1, -1}) {
            QVec e{0, 0, 0};
            e[static_cast<std::size_t>(k)] = -s;  // -e = c: the contacts hold s e_k
            if (!oracle::applied_in_mode(reference::QMat{zero, zero, zero}, c.n, c.t, {g},
                                         std::string(scene.contacts.size(), 's'), e)) {
                return false;
            }
        }
    }
    return true;
}

// A failing test's certificate: w != 0 with w . g >= 0 for every generator, from raw numbers.
void expect_certificate(const Scene& scene, const ClosureTest& t, bool force) {
    ASSERT_TRUE(t.unresisted.has_value());
    const QVec w = reference::to_q(*t.unresisted);
    EXPECT_FALSE(reference::is_zero(w));
    for (const QVec& g : raw_generators(scene, force)) EXPECT_GE(reference::sign(reference::dot(w, g)), 0);
}

// The quality computed here from its definition (docs/design.md, "Closure"): the contacts' unit
// wrenches (u, (p - c) x u / L), u the unit normal (form) or the unit friction-cone edges n +- mu t
// (force), c the centre of mass (the contacts' centroid without a body), L the largest distance of
// a contact from c; the radius of the largest ball about 0 inside their convex hull is the least
// distance from 0 to a facet plane of the hull, whose facets cddlib gives (exact rationals of the
// rounded unit wrenches). Shares nothing with mechanics/closure.cpp.
double quality_by_definition(const Scene& scene, bool force) {
    Vec2 c = Vec2::Zero();
    if (scene.body) {
        c = scene.body->com;
    } else {
        for (const Contact& contact : scene.contacts) c += contact.point;
        c /= static_cast<double>(scene.contacts.size());
    }
    double length = 0.0;
    for (const Contact& contact : scene.contacts) length = std::max(length, (contact.point - c).norm());
    if (length == 0.0) length = 1.0;
    std::vector<Vec3> units;
    for (const Contact& contact : scene.contacts) {
        const Vec2 t(contact.normal.y(), -contact.normal.x());
        std::vector<Vec2> forces{contact.normal};
        if (force) forces = {contact.normal + contact.mu * t, contact.normal - contact.mu * t};
        for (Vec2 f : forces) {
            f.normalize();
            const Vec2 r = contact.point - c;
            units.emplace_back(f.x(), f.y(), (r.x() * f.y() - r.y() * f.x()) / length);
        }
    }
    double radius = std::numeric_limits<double>::infinity();
    for (const auto& [b, a] : oracle::hull_facets(units)) radius = std::min(radius, b.get_d() / reference::to_vec3(a).norm());
    return radius;
}

// The quality against the definition, in (0, 1].
void expect_quality(const Scene& scene, const Closure& c, bool force) {
    const double q = force ? c.force.quality : c.form.quality;
    EXPECT_NEAR(q, quality_by_definition(scene, force), 1e-12);
    EXPECT_GT(q, 0.0);
    EXPECT_LE(q, 1.0);
}

// Four frictionless contacts at the side midpoints of a square, normals through its centre:
// every normal's wrench has zero torque about the centre (the origin), so the cone is the plane
// tau = 0 and a pure torque (0, 0, +-1) cannot be resisted, nor the turn about the centre
// stopped (Modern Robotics, ch. 12): no form closure, and with mu = 0 no force closure.
TEST(Closure, FourMidpointsOfASquareAreNoClosure) {
    const Scene scene = testing::example_scene("closure-four-midpoints.json");
    const Closure c = closure(scene);
    EXPECT_FALSE(c.form.holds);
    EXPECT_FALSE(c.force.holds);
    expect_certificate(scene, c.form, false);
    const Vec3 w = c.form.unresisted->value();
    EXPECT_EQ(w.x(), 0.0);
    EXPECT_EQ(w.y(), 0.0);
    EXPECT_NE(w.z(), 0.0);
}

// Moving the bottom contact's force to two, at x = -1/2 and x = 1/2: wrenches (0, 1, -1/2),
// (0, 1, 1/2), (-1, 0, 0), (0, -1, 0), (1, 0, 0). Their sums give (0, 0, +-1/2) with the top
// contact's (0, -1, 0), and +-x, +-y directly: they positively span R^3, form closure. Without
// the top contact nothing pushes along -y, so nothing resists a force up: the certificate points
// up (and translating up moves no contact into its obstacle).
TEST(Closure, FiveContactsOfASquareAreFormClosure) {
    Scene scene = testing::example_scene("closure-five-contacts.json");
    const Closure c = closure(scene);
    EXPECT_TRUE(c.form.holds);
    EXPECT_TRUE(c.force.holds);  // mu = 0: the same cone
    EXPECT_EQ(c.reference, Vec2(0, 0));  // the centre of mass
    EXPECT_DOUBLE_EQ(c.length, std::sqrt(1.25));  // the bottom contacts, at (+-1/2, -1)
    expect_quality(scene, c, false);
    scene.contacts.erase(scene.contacts.begin() + 3);  // the top one
    const Closure without = closure(scene);
    EXPECT_FALSE(without.form.holds);
    expect_certificate(scene, without.form, false);
    const Vec3 w = without.form.unresisted->value();
    EXPECT_GT(w.y(), 0.0);
}

// Two fingers at (-1, 1/4) and (1, 0) with mu = 1/2, pressing along x: the line between them,
// direction (2, -1/4), is 7.1 degrees from both normals, inside both friction cones (26.6
// degrees): force closure (Nguyen 1988). Frictionless, two contacts never span R^3.
TEST(Closure, AntipodalFrictionalFingersAreForceClosure) {
    Scene scene = testing::example_scene("closure-antipodal-fingers.json");
    const Closure c = closure(scene);
    EXPECT_FALSE(c.form.holds);
    EXPECT_TRUE(c.force.holds);
    expect_certificate(scene, c.form, false);
    expect_quality(scene, c, true);
    // With mu = 0.1 (5.7 degrees) the line leaves the cones: no force closure.
    for (Contact& contact : scene.contacts) contact.mu = contact.mu_kinetic = 0.1;
    const Closure low = closure(scene);
    EXPECT_FALSE(low.force.holds);
    expect_certificate(scene, low.force, true);
}

TEST(Closure, AgreesWithTheExactLpOnRandomGrasps) {
    testing::Random rnd(909);
    int held_form = 0, held_force = 0, scenes = 0;
    for (int s = 0; s < testing::sized(300); ++s) {
        Scene scene;
        const int n = rnd.integer(2, 6);
        const Vec2 centre(rnd.integer(-2, 2), rnd.integer(-2, 2));
        for (int j = 0; j < n; ++j) {
            const Vec2 p(rnd.integer(-4, 4) * 0.5, rnd.integer(-4, 4) * 0.5);
            Vec2 normal = s % 3 == 0 ? Vec2(centre - p) : testing::slanted_direction(rnd);  // concurrent third
            if (normal.isZero()) normal = Vec2(0, 1);
            scene.contacts.push_back(Contact::make(p, normal, rnd.integer(0, 4) * 0.25));
        }
        const Closure c = closure(scene);
        EXPECT_EQ(c.form.holds, oracle_spans(scene, false)) << "scene " << s;
        EXPECT_EQ(c.force.holds, oracle_spans(scene, true)) << "scene " << s;
        if (!c.form.holds) expect_certificate(scene, c.form, false);
        if (!c.force.holds) expect_certificate(scene, c.force, true);
        if (c.form.holds) expect_quality(scene, c, false);
        if (c.force.holds) expect_quality(scene, c, true);
        held_form += c.form.holds;
        held_force += c.force.holds;
        ++scenes;
    }
    std::cout << "[Closure] " << scenes << " random grasps: form closure " << held_form << ", force closure "
              << held_force << "\n";
    EXPECT_GE(held_form, testing::floor_of(10));
    EXPECT_GE(held_force, testing::floor_of(30));
    EXPECT_LT(held_force, scenes);
}

TEST(Closure, RefusesWhatItCannotAnswer) {
    EXPECT_THROW((void)closure(Scene{}), std::invalid_argument);
    const Scene scene = testing::example_scene("closure-five-contacts.json");
    EXPECT_THROW((void)closure(scene, ClosureOptions{std::nullopt, 0.0}), std::invalid_argument);
    EXPECT_THROW((void)closure(scene, ClosureOptions{std::nullopt, std::nan("")}), std::invalid_argument);
}

}  // namespace
}  // namespace momentlab
