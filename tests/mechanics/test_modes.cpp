// Contact modes: answers known by hand, agreement with a brute-force exact LP oracle (fed the
// scenes' raw numbers in rationals) on random and exactly degenerate scenes with slanted
// normals, and invariance under exact transforms.
#include <gtest/gtest.h>

#include "mechanics/mode_walk.hpp"

#include <map>
#include <set>
#include <sstream>

#include "../common/scenes.hpp"
#include "mode_oracle.hpp"
#include "random_inputs.hpp"
#include "momentlab/mechanics/modes.hpp"

namespace momentlab {
namespace {

std::set<std::string> mode_strings(const std::vector<Contact>& contacts) {
    std::set<std::string> out;
    const ModeSet set = enumerate_modes(contacts);
    for (const Mode& m : set.modes) EXPECT_TRUE(out.insert(m.letters).second) << "repeated " << m.letters;
    EXPECT_EQ(set.modes.front().letters, std::string(contacts.size(), 'f'));
    return out;
}

Contact contact(double x, double y, double nx, double ny) {
    return Contact::make(Vec2(x, y), Vec2(nx, ny), 0.5);
}

TEST(Modes, OneContactHasFourModes) {
    EXPECT_EQ(mode_strings({contact(3, 1, 1, 2)}), (std::set<std::string>{"s", "f", "r", "l"}));
}

TEST(Modes, CollinearFloorContactsHaveTenModes) {
    // The list for three contacts; the same shape for two and for five.
    EXPECT_EQ(mode_strings({contact(0, 0, 0, 1), contact(1, 0, 0, 1), contact(2, 0, 0, 1)}),
              (std::set<std::string>{"fff", "sss", "fss", "ssf", "rss", "lss", "ssr", "ssl", "rrr", "lll"}));
    EXPECT_EQ(mode_strings({contact(0, 0, 0, 1), contact(1, 0, 0, 1)}).size(), 10u);
    std::vector<Contact> five;
    for (int i = 0; i < 5; ++i) five.push_back(contact(i * 0.5, 0, 0, 1));
    EXPECT_EQ(mode_strings(five).size(), 10u);
}

TEST(Modes, BlockInACornerAndBetweenWalls) {
    // A box on a floor (two contacts) and against a wall on its left (normal +x).
    const std::vector<Contact> corner = {contact(0, 0, 0, 1), contact(1, 0, 0, 1), contact(0, 0.5, 1, 0)};
    const auto modes = mode_strings(corner);
    EXPECT_TRUE(modes.count("sss"));
    EXPECT_TRUE(modes.count("rrs"));   // slides right along the floor, away from the wall
    EXPECT_FALSE(modes.count("lls"));  // cannot slide into the wall
    // Squeezed between two parallel walls: no separation of one without the other turning.
    const std::vector<Contact> squeezed = {contact(0, 0, 1, 0), contact(1, 0, -1, 0)};
    EXPECT_EQ(mode_strings(squeezed), testing::exact_modes(squeezed));
}

// Random scenes with 1..6 contacts: general doubles, and exactly degenerate ones (parallel
// normals, collinear and coincident points, small integers).
std::vector<Contact> random_scene(testing::Random& rnd, int kind) {
    const int n = rnd.integer(1, 6);
    std::vector<Contact> c;
    const Vec2 shared_normal(rnd.integer(-2, 2), rnd.integer(1, 2));
    for (int i = 0; i < n; ++i) {
        Vec2 p, nrm;
        switch (kind % 4) {
            case 0:  // general doubles
                p = Vec2(rnd.uniform(-2, 2), rnd.uniform(-2, 2));
                nrm = Vec2(rnd.uniform(-1, 1), rnd.uniform(-1, 1));
                break;
            case 1:  // small integers
                p = Vec2(rnd.integer(-2, 2), rnd.integer(-2, 2));
                nrm = Vec2(rnd.integer(-2, 2), rnd.integer(-2, 2));
                break;
            case 2:  // parallel normals, collinear points
                p = Vec2(rnd.integer(-3, 3), 0);
                nrm = rnd.integer(0, 3) ? shared_normal : Vec2(-shared_normal);
                break;
            default:  // coincident points, axis normals
                p = Vec2(rnd.integer(0, 1), rnd.integer(0, 1));
                nrm = rnd.integer(0, 1) ? Vec2(rnd.integer(-1, 1), 1) : Vec2(1, rnd.integer(-1, 1));
                break;
        }
        if (nrm.x() == 0 && nrm.y() == 0) nrm = Vec2(0, 1);
        c.push_back(Contact::make(p, nrm, 0.3));
    }
    return c;
}

std::string joined(const std::set<std::string>& modes) {
    std::string out;
    for (const auto& m : modes) out += m + " ";
    return out;
}

std::string describe(const std::vector<Contact>& contacts) {
    std::ostringstream where;
    where.precision(17);
    for (const Contact& c : contacts) where << "(" << c.point.transpose() << " n " << c.normal.transpose() << ") ";
    return where.str();
}

TEST(Modes, AgreeWithExactLpOracle) {
    testing::Random rnd(314);
    int scenes = 0, failures = 0, total_modes = 0;
    for (int i = 0; i < 1200 && failures < 10; ++i) {
        const auto contacts = random_scene(rnd, i);
        const auto ours = mode_strings(contacts);
        const auto expected = testing::exact_modes(contacts);
        ++scenes;
        total_modes += static_cast<int>(expected.size());
        if (ours != expected) {
            ++failures;
            ADD_FAILURE() << "ours: " << joined(ours) << "\noracle: " << joined(expected) << "\nscene: " << describe(contacts);
        }
    }
    std::cout << "[Modes] " << scenes << " scenes, " << total_modes << " modes, " << failures << " disagreements\n";
    EXPECT_EQ(failures, 0);
    EXPECT_EQ(scenes, 1200);
    EXPECT_GE(total_modes, 9000);  // README.md: "more than 9,000 modes"
}

// The scenes of the exactness issue, by hand: a wheel held at (5, 0), (3, 4) and (-3, -4) by
// normals through its centre (written with lengths 5, 5 and 5). Contacts 2 and 3 face each
// other on one line, so neither can separate alone: the exact modes are fixed, both rolling
// senses (lll, rrr: a rotation about the centre slides every contact the same way), and the
// motions that lift contact 1 (s..): a rotation about a point of the line through contacts 2
// and 3 slides them in the same sense, or fixes one (the centre of rotation at it).
TEST(Modes, WheelWithNormalsThroughItsCentre) {
    const std::vector<Contact> wheel = {Contact::make(Vec2(5, 0), Vec2(-5, 0), 0), Contact::make(Vec2(3, 4), Vec2(-3, -4), 0),
                                        Contact::make(Vec2(-3, -4), Vec2(3, 4), 0)};
    const std::set<std::string> expected = {"fff", "lll", "rrr", "sfl", "sll", "srf", "srl", "srr"};
    EXPECT_EQ(mode_strings(wheel), expected);
    EXPECT_EQ(testing::exact_modes(wheel), expected);
    // Two contacts where the first one's normal line (x = 1.25) passes through the second
    // point: rotating about the second point keeps it fixed and slides the first sideways (lf,
    // rf), a knife edge that rounding the slanted normal (2, 1) to unit length lost. The same
    // scene translated exactly by (-0.25, -0.125) has the same modes.
    const std::vector<Contact> pair = {Contact::make(Vec2(1.25, -0.875), Vec2(0, 1), 0),
                                       Contact::make(Vec2(1.25, 0.125), Vec2(2, 1), 0)};
    const auto modes = mode_strings(pair);
    EXPECT_EQ(modes, testing::exact_modes(pair));
    EXPECT_TRUE(modes.count("lf") && modes.count("rf")) << joined(modes);
    const std::vector<Contact> moved = {Contact::make(Vec2(1.0, -1.0), Vec2(0, 1), 0),
                                        Contact::make(Vec2(1.0, 0.0), Vec2(2, 1), 0)};
    EXPECT_EQ(mode_strings(moved), modes);
}

// At least 1,000 scenes with slanted normals in the families of the issue (concurrent, on a
// circle, parallel, collinear, slanted integers; a third of them moved 2^20 .. 2^40 away from
// the origin), each compared with the brute-force oracle and under a random exact transform
// with itself.
TEST(Modes, SlantedNormalsAgreeWithOracleAndUnderExactTransforms) {
    testing::Random rnd(20261123);
    const testing::SceneFamily families[] = {testing::SceneFamily::Concurrent, testing::SceneFamily::OnACircle,
                                             testing::SceneFamily::Parallel, testing::SceneFamily::Collinear,
                                             testing::SceneFamily::SlantedIntegers};
    int scenes = 0, transformed = 0, failures = 0, far = 0;
    std::map<std::string, int> transforms;
    for (int i = 0; i < 1100 && failures < 10; ++i) {
        const auto family = families[i % 5];
        const bool is_far = i % 3 == 2;
        const Scene scene = testing::random_scene(rnd, family, 4, is_far);
        const auto ours = mode_strings(scene.contacts);
        const auto expected = testing::exact_modes(scene.contacts);
        ++scenes;
        far += is_far;
        if (ours != expected) {
            ++failures;
            ADD_FAILURE() << testing::scene_family_name(family) << ": ours " << joined(ours) << "\noracle: "
                          << joined(expected) << "\nscene: " << describe(scene.contacts);
            continue;
        }
        const testing::Transform t = testing::random_transform(rnd, scene.contacts.size());
        if (!testing::exactly_representable(t, scene)) continue;
        std::set<std::string> renamed;
        for (const std::string& m : ours) renamed.insert(t.letters(m));
        const auto after = mode_strings(t.apply(scene).contacts);
        ++transformed;
        ++transforms[t.name];
        if (after != renamed) {
            ++failures;
            ADD_FAILURE() << t.name << " of " << testing::scene_family_name(family) << ": " << joined(after)
                          << "\nexpected " << joined(renamed) << "\nscene: " << describe(scene.contacts);
        }
    }
    std::cout << "[Modes] slanted normals: " << scenes << " scenes (" << far << " far from the origin), "
              << transformed << " transformed exactly (";
    for (const auto& [k, v] : transforms) std::cout << k << " " << v << ", ";
    std::cout << "), " << failures << " disagreements\n";
    EXPECT_EQ(failures, 0);
    EXPECT_GE(scenes, 1000);
    EXPECT_GE(transformed, 900);
    for (const auto& [k, v] : transforms) EXPECT_GE(v, 100) << k;
}

// Which contacts are closed on each face, found the two ways the walk has: locating each N_j
// among A's facet normals (taken on cones of more than 16 faces), and testing every contact on
// every face (the definition, N_j . g = 0 for each generator g of the face). Both must hand on
// the same cells: index, face, closed contacts, letters and closure, in the same order. The
// scenes have many contacts on slanted, concurrent, circular and integer normals, with exact
// duplicates and normals on the boundary of cone(N_j), so that A has many faces.
TEST(Modes, LocatingClosedContactsAgreesWithTestingEveryFace) {
    testing::Random rnd(20261125);
    const testing::SceneFamily families[] = {testing::SceneFamily::Concurrent, testing::SceneFamily::OnACircle,
                                             testing::SceneFamily::SlantedIntegers, testing::SceneFamily::GeneralDoubles};
    int located = 0, cells = 0;
    // Floor contacts (normal +y) and wall contacts (normal +-x) at integer points, and contacts
    // where a floor's normal line meets a wall's, with the sum of their normals: exactly
    // N_j + N_k, so on A*'s facet between them whenever those two are neighbouring extreme rays.
    const auto floors_and_walls = [&] {
        Scene scene;
        std::vector<Contact> floors, walls;
        for (int k = rnd.integer(2, 8); k > 0; --k) floors.push_back(Contact::make(Vec2(rnd.integer(-4, 4), rnd.integer(-2, 2)), Vec2(0, 1), 0.5));
        for (int k = rnd.integer(1, 6); k > 0; --k) {
            walls.push_back(Contact::make(Vec2(rnd.integer(-4, 4), rnd.integer(-2, 4)), Vec2(rnd.integer(0, 1) ? 1 : -1, 0), 0.3));
        }
        scene.contacts = floors;
        scene.contacts.insert(scene.contacts.end(), walls.begin(), walls.end());
        for (int k = rnd.integer(1, 6); k > 0; --k) {
            const Contact& f = floors[static_cast<std::size_t>(rnd.integer(0, static_cast<int>(floors.size()) - 1))];
            const Contact& w = walls[static_cast<std::size_t>(rnd.integer(0, static_cast<int>(walls.size()) - 1))];
            scene.contacts.push_back(Contact::make(Vec2(f.point.x(), w.point.y()), f.normal + w.normal, 0.4));
        }
        return scene;
    };
    for (int i = 0; i < 406; ++i) {
        Scene scene = i % 5 == 4 || i >= 400 ? floors_and_walls() : testing::random_scene(rnd, families[i % 4], 40, i % 3 == 2);
        if (i % 2 == 1 && !scene.contacts.empty()) {  // exact repeats: the same normal line twice
            for (int r = 0; r < 4; ++r) scene.contacts.push_back(scene.contacts[static_cast<std::size_t>(rnd.integer(0, static_cast<int>(scene.contacts.size()) - 1))]);
        }
        // The last six: over 2,000 contacts (repeats in random order), whose searches are shared
        // out to two threads and joined.
        while (i >= 400 && scene.contacts.size() < 2100) {
            scene.contacts.push_back(scene.contacts[static_cast<std::size_t>(rnd.integer(0, static_cast<int>(scene.contacts.size()) - 1))]);
        }
        struct Seen {
            std::size_t index, face;
            std::vector<int> closed;
            std::string letters;
            std::size_t closure;
            bool operator==(const Seen&) const = default;
        };
        const auto walk = [&](detail::ModeWalk::Closed how) {
            std::vector<Seen> out;
            detail::ModeWalk(scene.contacts, how).run(nullptr, [&](const detail::WalkCell& c) {
                out.push_back({c.index, c.face, {c.closed.begin(), c.closed.end()}, {c.letters.begin(), c.letters.end()}, c.closure->size()});
            });
            return out;
        };
        const auto tested = walk(detail::ModeWalk::Closed::Test);
        const auto by_location = walk(detail::ModeWalk::Closed::Locate);
        EXPECT_TRUE(tested == by_location) << "scene " << i << ": " << describe(scene.contacts);
        const Cone a = detail::ModeWalk(scene.contacts).feasible_twists();
        located += a.dimension() == 3 && a.is_pointed() && a.facets().size() >= 3;
        cells += static_cast<int>(tested.size());
    }
    std::cout << "[Modes] closed contacts located on " << located << " scenes with a pointed A, " << cells << " cells\n";
    EXPECT_GE(located, 40);
}

}  // namespace
}  // namespace momentlab
