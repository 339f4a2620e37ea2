// The public functions' documented preconditions (docs/reliability.md, "Library
// preconditions"): each violation is a std::invalid_argument, never a crash or a wrong answer.
#include <gtest/gtest.h>

#include <limits>
#include <stdexcept>

#include "momentlab/mechanics/advanced.hpp"
#include "momentlab/geometry/force_sets.hpp"
#include "momentlab/geometry/labels.hpp"
#include "momentlab/mechanics/query_index.hpp"
#include "momentlab/mechanics/find_contacts.hpp"

namespace momentlab {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

Scene one_contact() {
    Scene s;
    s.body = Body{1.0, Vec2(0, 0.5), 0.1, {}};
    s.contacts = {Contact::make(Vec2(0, 0), Vec2(0, 1), 0.5)};
    return s;
}

TEST(Preconditions, ConesAndForceSets) {
    const std::vector<Vec3> bad = {Vec3(1, 0, 0), Vec3(kNaN, 0, 0)};
    EXPECT_THROW((void)Cone::from_generators(bad), std::invalid_argument);
    EXPECT_THROW((void)Cone::from_halfspaces(std::vector<Vec3>{Vec3(0, kInf, 0)}), std::invalid_argument);
    EXPECT_THROW((void)force_ray(Vec2(0, 0), Vec2(0, 0)), std::invalid_argument);
    EXPECT_THROW((void)line_of_force(Vec2(kNaN, 0), Vec2(1, 0)), std::invalid_argument);
    EXPECT_THROW((void)friction_cone(Vec2(0, 0), Vec2(0, 1), -0.1), std::invalid_argument);
    EXPECT_THROW((void)friction_cone(Vec2(0, 0), Vec2(0, 1), kNaN), std::invalid_argument);
    const Labels labels(friction_cone(Vec2(0, 0), Vec2(0, 1), 0.5));
    EXPECT_THROW((void)labels.at(Vec2(kNaN, 0)), std::invalid_argument);
}

TEST(Preconditions, Contacts) {
    EXPECT_THROW((void)Contact::make(Vec2(0, 0), Vec2(0, 0), 0.5), std::invalid_argument);
    EXPECT_THROW((void)Contact::make(Vec2(kInf, 0), Vec2(0, 1), 0.5), std::invalid_argument);
    EXPECT_THROW((void)Contact::make(Vec2(0, 0), Vec2(0, 1), -1), std::invalid_argument);
    EXPECT_THROW((void)Contact::make(Vec2(0, 0), Vec2(0, 1), 0.5, -0.5), std::invalid_argument);
    // Contacts built by hand bypass make: enumerate_modes checks them itself.
    for (auto spoil : {+[](Contact& c) { c.normal = Vec2(0, 0); }, +[](Contact& c) { c.point.x() = kNaN; },
                       +[](Contact& c) { c.mu = -1; }, +[](Contact& c) { c.mu_kinetic = kInf; }}) {
        std::vector<Contact> contacts = one_contact().contacts;
        spoil(contacts[0]);
        EXPECT_THROW((void)enumerate_modes(contacts), std::invalid_argument);
    }
}

TEST(Preconditions, BodiesAndQueries) {
    Scene s = one_contact();
    s.body->mass = 0;
    EXPECT_THROW((void)analyze(s), std::invalid_argument);
    s = one_contact();
    s.body->inertia = -1;
    EXPECT_THROW((void)analyze(s), std::invalid_argument);
    s = one_contact();
    s.body->com = Vec2(kNaN, 0);
    EXPECT_THROW((void)analyze(s), std::invalid_argument);
    s = one_contact();
    s.body.reset();
    EXPECT_THROW((void)analyze(s), std::invalid_argument);
    const auto a = analyze(one_contact());
    EXPECT_THROW((void)query(a, Vec3(0, kNaN, 0)), std::invalid_argument);
    EXPECT_THROW((void)QueryIndex(a).query(Vec3(kInf, 0, 0)), std::invalid_argument);
}

TEST(Preconditions, Polygons) {
    const Polygon square = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    const Polygon bow_tie = {{0, -1}, {1, 0}, {1, -1}, {0, 0}};
    const Polygon floor = {{-1, -1}, {2, -1}, {2, 0}, {-1, 0}};
    EXPECT_THROW((void)find_contacts(bow_tie, {floor}), std::invalid_argument);
    EXPECT_THROW((void)find_contacts(square, {bow_tie}), std::invalid_argument);
    EXPECT_THROW((void)find_contacts(square, {floor}, ContactFinding{-1.0, 0.0, 0.0}), std::invalid_argument);
    EXPECT_EQ(find_contacts(square, {floor}).size(), 2U);  // the two bottom corners
}

}  // namespace
}  // namespace momentlab
