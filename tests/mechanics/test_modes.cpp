// Contact modes: answers known by hand, and agreement with a brute-force exact LP oracle on
// random and exactly degenerate scenes.
#include <gtest/gtest.h>

#include <set>
#include <sstream>

#include "../common/random_inputs.hpp"
#include "../oracle/lp_oracle.hpp"
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
    EXPECT_EQ(mode_strings(squeezed), oracle::all_modes({squeezed[0].normal_wrench(), squeezed[1].normal_wrench()},
                                                         {squeezed[0].tangent_wrench(), squeezed[1].tangent_wrench()}));
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

TEST(Modes, AgreeWithExactLpOracle) {
    testing::Random rnd(314);
    int scenes = 0, failures = 0, total_modes = 0;
    for (int i = 0; i < 1200 && failures < 10; ++i) {
        const auto contacts = random_scene(rnd, i);
        std::vector<Vec3> n, t;
        for (const Contact& c : contacts) {
            n.push_back(c.normal_wrench());
            t.push_back(c.tangent_wrench());
        }
        const auto ours = mode_strings(contacts);
        const auto expected = oracle::all_modes(n, t);
        ++scenes;
        total_modes += static_cast<int>(expected.size());
        if (ours != expected) {
            ++failures;
            std::string a, b;
            for (const auto& m : ours) a += m + " ";
            for (const auto& m : expected) b += m + " ";
            std::ostringstream where;
            where.precision(17);
            for (const Contact& c : contacts) {
                where << "(" << c.point.transpose() << " n " << c.normal.transpose() << ") ";
            }
            ADD_FAILURE() << "ours: " << a << "\noracle: " << b << "\nscene: " << where.str();
        }
    }
    std::cout << "[Modes] " << scenes << " scenes, " << total_modes << " modes, " << failures << " disagreements\n";
    EXPECT_EQ(failures, 0);
}

}  // namespace
}  // namespace momentlab
