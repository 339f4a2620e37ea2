// Contacts found from polygons, checked against the contacts written by hand.
#include <gtest/gtest.h>
#include <gmpxx.h>

#include <algorithm>
#include <cmath>
#include <random>

#include <fstream>
#include <sstream>

#include "momentlab/io/scene_json.hpp"
#include "momentlab/geometry/polygon.hpp"
#include "momentlab/mechanics/find_contacts.hpp"

namespace momentlab {
namespace {

bool has_contact(const std::vector<Contact>& cs, const Vec2& p, const Vec2& n) {
    return std::any_of(cs.begin(), cs.end(), [&](const Contact& c) {
        return (c.point - p).norm() < 1e-12 && (c.normal - n).norm() < 1e-12;
    });
}

const Polygon kBlock = {{0, 0}, {1, 0}, {1, 0.5}, {0, 0.5}};

TEST(FindContacts, BlockOnATableTouchesAtItsBottomCorners) {
    const Polygon table = {{-2, -1}, {3, -1}, {3, 0}, {-2, 0}};
    const auto cs = find_contacts(kBlock, {table});
    ASSERT_EQ(cs.size(), 2u);
    EXPECT_TRUE(has_contact(cs, Vec2(0, 0), Vec2(0, 1)));
    EXPECT_TRUE(has_contact(cs, Vec2(1, 0), Vec2(0, 1)));
    // Either orientation of either polygon.
    Polygon cw = table;
    std::reverse(cw.begin(), cw.end());
    EXPECT_EQ(find_contacts(kBlock, {cw}).size(), 2u);
}

TEST(FindContacts, EdgeOverlapEndsAtTheSmallerEdge) {
    // A narrow post under the block: the overlap is the post's top, x in [0.25, 0.5].
    const Polygon post = {{0.25, -1}, {0.5, -1}, {0.5, 0}, {0.25, 0}};
    const auto cs = find_contacts(kBlock, {post});
    ASSERT_EQ(cs.size(), 2u);
    EXPECT_TRUE(has_contact(cs, Vec2(0.25, 0), Vec2(0, 1)));
    EXPECT_TRUE(has_contact(cs, Vec2(0.5, 0), Vec2(0, 1)));
}

TEST(FindContacts, CornerOnCornerIsConstrainedByBothObstacleEdges) {
    // The block's corner (0, 0) on the table's corner (0, 0): the non-penetrating motions
    // form a non-convex set no point contacts represent. momentlab gives the body vertex one
    // contact per obstacle edge ending there (docs/formats.md): it over-constrains (sliding
    // left is forbidden too). The table's own corner adds nothing (left to the body vertex).
    const Polygon table = {{-2, -1}, {0, -1}, {0, 0}, {-2, 0}};
    const auto cs = find_contacts(kBlock, {table});
    ASSERT_EQ(cs.size(), 2u);
    EXPECT_TRUE(has_contact(cs, Vec2(0, 0), Vec2(0, 1)));
    EXPECT_TRUE(has_contact(cs, Vec2(0, 0), Vec2(1, 0)));
}

// Where each contact was found, by hand: the block's vertex (0, 0) on the table's corner touches
// the table's edge 1 ((0, -1) to (0, 0), outward normal (1, 0)) and edge 2 ((0, 0) to (-2, 0),
// outward (0, 1)); the block's vertex is its vertex 0 as given, or 3 when given clockwise, and the
// table's edges 1 and 2 are its edges 1 and 0 when it is given clockwise.
TEST(FindContacts, OriginsNameTheVertexAndEdgeAsGiven) {
    const Polygon table = {{-2, -1}, {0, -1}, {0, 0}, {-2, 0}};
    for (const bool block_clockwise : {false, true}) {
        for (const bool table_clockwise : {false, true}) {
            Polygon block = kBlock, obstacle = table;
            if (block_clockwise) std::reverse(block.begin(), block.end());
            if (table_clockwise) std::reverse(obstacle.begin(), obstacle.end());
            std::vector<ContactOrigin> origins;
            const auto cs = detail::find_contacts_of_simple(block, {obstacle}, {}, &origins);
            ASSERT_EQ(cs.size(), 2u);
            ASSERT_EQ(origins.size(), 2u);
            for (std::size_t j = 0; j < 2; ++j) {
                EXPECT_TRUE(origins[j].body_vertex);
                EXPECT_EQ(origins[j].obstacle, 0u);
                EXPECT_EQ(origins[j].vertex, block_clockwise ? 3u : 0u);
                const std::size_t edge = cs[j].normal.x() > 0 ? 1 : 2;  // (1, 0) or (0, 1)
                EXPECT_EQ(origins[j].edge, table_clockwise ? 2 - edge : edge) << block_clockwise << table_clockwise;
            }
        }
    }
    // A table vertex on the block's edge: the post's corner (0.5, 0) on the block's edge 0.
    const Polygon post = {{0.5, -1}, {2, -1}, {2, 0}, {0.5, 0}};
    std::vector<ContactOrigin> origins;
    const auto cs = detail::find_contacts_of_simple(kBlock, {post}, {}, &origins);
    ASSERT_EQ(cs.size(), 2u);  // the block's corner (1, 0) on the post's top edge 2, and the post's corner
    EXPECT_TRUE(has_contact(cs, Vec2(0.5, 0), Vec2(0, 1)));
    for (std::size_t j = 0; j < 2; ++j) {
        const bool at_post_corner = cs[j].point.x() == 0.5;
        EXPECT_EQ(origins[j].body_vertex, !at_post_corner);
        EXPECT_EQ(origins[j].vertex, at_post_corner ? 3u : 1u);
        EXPECT_EQ(origins[j].edge, at_post_corner ? 0u : 2u);
    }
    // Read from a file: one origin per contact found, none for contacts written out.
    const Scene found = read_scene_text(R"({"body": {"mass": 1, "com": [0.5, 0.25], "inertia": 1,
        "polygon": [[0, 0], [1, 0], [1, 0.5], [0, 0.5]]}, "obstacles": [{"polygon": [[-2, -1], [3, -1], [3, 0], [-2, 0]]}]})");
    EXPECT_EQ(found.origins.size(), found.contacts.size());
    EXPECT_EQ(found.contacts.size(), 2u);
    const Scene written = read_scene_text(R"({"contacts": [{"point": [0, 0], "normal": [0, 1]}]})");
    EXPECT_TRUE(written.origins.empty());
}

TEST(FindContacts, ExampleOutlinesGiveTheWrittenContacts) {
    // Each bundled scene writes its contacts by hand and gives the polygons: finding them from
    // the polygons must give the same points and normals.
    for (const char* name : {"block-on-table.json", "figure-3-block-along-wall.json",
                             "figure-4-peg-in-hole.json", "rod-in-corner.json"}) {
        std::ifstream in(std::string(MOMENTLAB_EXAMPLES) + "/" + name);
        std::ostringstream text;
        text << in.rdbuf();
        const Scene written = read_scene_text(text.str());
        const auto found = find_contacts(written.body->polygon, written.obstacles);
        ASSERT_EQ(found.size(), written.contacts.size()) << name;
        for (const Contact& c : written.contacts) EXPECT_TRUE(has_contact(found, c.point, c.normal)) << name;
    }
}

TEST(FindContacts, VertexOnAWallAndTheThreshold) {
    // A triangle leaning on a wall x = 0 with its vertex at (1e-10, 1): within the default
    // threshold 1e-9; with a threshold of 1e-12 it does not touch.
    const Polygon tri = {{1e-10, 1}, {2, 0}, {2, 2}};
    const Polygon wall = {{-1, -5}, {0, -5}, {0, 5}, {-1, 5}};
    EXPECT_EQ(find_contacts(tri, {wall}).size(), 1u);
    EXPECT_TRUE(has_contact(find_contacts(tri, {wall}), Vec2(1e-10, 1), Vec2(1, 0)));
    EXPECT_TRUE(find_contacts(tri, {wall}, ContactFinding{.distance = 1e-12}).empty());
}

TEST(FindContacts, SceneWithoutContactsFindsThem) {
    const Scene s = read_scene_text(R"({"body": {"mass": 1, "com": [0.5, 0.25], "inertia": 0.1,
        "polygon": [[0, 0], [1, 0], [1, 0.5], [0, 0.5]]}, "mu": 0.5,
        "obstacles": [{"polygon": [[-2, -1], [3, -1], [3, 0], [-2, 0]]}]})");
    ASSERT_EQ(s.contacts.size(), 2u);
    EXPECT_DOUBLE_EQ(s.contacts[0].mu, 0.5);
    EXPECT_THROW((void)read_scene_text(R"({"body": {"mass": 1, "com": [0, 0], "inertia": 1}})"), InputError);
}

// find_contacts indexes the touched polygon's edges in a grid; against the plain double loop over
// every vertex and edge (the rules of find_contacts.hpp written out here, each distance test in
// exact rationals: rounded, a neighbour exactly on the edge's line was once taken as inside) on random outlines
// that touch often: star-shaped polygons on a coarse grid, the obstacle a copy moved so that
// vertices land on edges, both orientations, distances 0 and 1e-9.
// |v - a| <= d, and x beyond the line of the counter-clockwise edge ab on its inner side by more
// than d ((b - a) x (x - a) > d |b - a|), in exact rationals.
bool near_exactly(const Vec2& v, const Vec2& a, double d) {
    const mpq_class dx = mpq_class(v.x()) - a.x(), dy = mpq_class(v.y()) - a.y(), dd = d;
    return dx * dx + dy * dy <= dd * dd;
}
bool inside_beyond(const Vec2& x, const Vec2& a, const Vec2& b, double d) {
    const mpq_class ex = mpq_class(b.x()) - a.x(), ey = mpq_class(b.y()) - a.y();
    const mpq_class cross = ex * (mpq_class(x.y()) - a.y()) - ey * (mpq_class(x.x()) - a.x()), dd = d;
    return sgn(cross) > 0 && cross * cross > dd * dd * (ex * ex + ey * ey);
}

std::vector<Contact> brute_force(const Polygon& body_in, const std::vector<Polygon>& obstacles, double distance) {
    const auto ccw = [](Polygon p) {
        if (!is_counter_clockwise(p)) std::reverse(p.begin(), p.end());
        return p;
    };
    const auto outward = [](const Vec2& a, const Vec2& b) -> Vec2 { return Vec2((b - a).y(), -(b - a).x()) / (b - a).norm(); };
    std::vector<Contact> found;
    const Polygon body = ccw(body_in);
    for (const Polygon& raw : obstacles) {
        const Polygon o = ccw(raw);
        for (int pass = 0; pass < 2; ++pass) {
            const Polygon& touching = pass == 0 ? body : o;
            const Polygon& touched = pass == 0 ? o : body;
            const std::size_t n = touching.size(), m = touched.size();
            for (std::size_t i = 0; i < n; ++i) {
                for (std::size_t k = 0; k < m; ++k) {
                    const Vec2 &v = touching[i], &a = touched[k], &b = touched[(k + 1) % m];
                    if (!within_distance_of_segment(v, a, b, distance)) continue;
                    if (pass == 1 && (near_exactly(v, a, distance) || near_exactly(v, b, distance))) continue;
                    const Vec2 out_n = outward(a, b);
                    if (inside_beyond(touching[(i + n - 1) % n], a, b, distance) || inside_beyond(touching[(i + 1) % n], a, b, distance)) {
                        continue;
                    }
                    found.push_back(Contact::make(v, pass == 0 ? out_n : Vec2(-out_n), 0.0, 0.0));
                }
            }
        }
    }
    std::vector<Contact> out;
    for (const Contact& c : found) {
        if (std::none_of(out.begin(), out.end(), [&](const Contact& d) {
                return near_exactly(c.point, d.point, distance) && (c.normal - d.normal).norm() <= distance;
            })) {
            out.push_back(c);
        }
    }
    return out;
}

TEST(FindContacts, TheGridFindsWhatTheDoubleLoopFinds) {
    std::mt19937 rng(5);
    int touching = 0;
    for (int t = 0; t < 400; ++t) {
        const int n = 5 + static_cast<int>(rng() % 40);
        Polygon body;
        for (int i = 0; i < n; ++i) {
            const double angle = 2 * M_PI * i / n;
            const double r = 1.0 + static_cast<double>(rng() % 3);
            body.emplace_back(std::round(r * std::cos(angle) * 4) / 4, std::round(r * std::sin(angle) * 4) / 4);
        }
        if (!polygon_problem(body).empty()) continue;
        Polygon obstacle;  // a box below, its top at the body's lowest y, or a shifted copy of the body
        double low = 1e9, left = 1e9, right = -1e9;
        for (const Vec2& v : body) {
            low = std::min(low, v.y());
            left = std::min(left, v.x());
            right = std::max(right, v.x());
        }
        if (t % 2 == 0) {
            obstacle = {{left - 1, low - 2}, {right + 1, low - 2}, {right + 1, low}, {left - 1, low}};
        } else {
            for (const Vec2& v : body) obstacle.emplace_back(v.x() + (right - left), v.y());
        }
        if (t % 3 == 0) std::reverse(obstacle.begin(), obstacle.end());
        if (!polygon_problem(obstacle).empty()) continue;
        for (double distance : {0.0, 1e-9}) {
            const std::vector<Contact> want = brute_force(body, {obstacle}, distance);
            const std::vector<Contact> got = find_contacts(body, {obstacle}, ContactFinding{distance, 0.0, 0.0});
            ASSERT_EQ(got.size(), want.size()) << "polygon " << t;
            for (std::size_t k = 0; k < got.size(); ++k) {
                EXPECT_EQ(got[k].point, want[k].point) << "polygon " << t;
                EXPECT_EQ(got[k].normal, want[k].normal) << "polygon " << t;
            }
            touching += got.empty() ? 0 : 1;
        }
    }
    EXPECT_GT(touching, 200);
}

// Many contacts on one vertical line (a comb against a wall): the merge of duplicates must not
// compare each with every other (it did when keyed by x alone); and two contacts a distance
// apart plus 2^-60 stay two.
TEST(FindContacts, ContactsAlongAWallAreMergedOnlyWithTheirNeighbours) {
    Polygon comb;  // teeth pointing to -x, their tips on x = 0
    const int teeth = 2000;
    comb.emplace_back(1.0, 0.0);
    for (int k = 0; k < teeth; ++k) {
        comb.emplace_back(0.0, 2.0 * k + 0.5);
        comb.emplace_back(0.5, 2.0 * k + 1.0);
    }
    comb.emplace_back(1.0, 2.0 * teeth);
    const Polygon wall = {{-1, -1}, {0, -1}, {0, 2.0 * teeth + 1}, {-1, 2.0 * teeth + 1}};
    const std::vector<Contact> found = find_contacts(comb, {wall});
    EXPECT_EQ(found.size(), static_cast<std::size_t>(teeth));
    const double e = 0x1p-60;
    const Polygon body = {{e, 0}, {1, 0}, {1, 10}, {e, 10}};
    const Polygon floor = {{-5, -5}, {5, -5}, {5, 0}, {-5, 0}};
    EXPECT_EQ(find_contacts(body, {floor}, ContactFinding{0.5, 0.0, 0.0}).size(), 2u);
}

// Review-33: far from the origin (x = 1e10, where x / 2d passes 2^62) two contacts 2^-31 apart
// along a wall, with one normal, are one at the distance 1e-9, and two at 2^-29 (1.9e-9) apart:
// the merge's grid once gave up there and compared only points whose doubles were equal.
TEST(FindContacts, ContactsFarFromTheOriginAreMergedWithinTheDistance) {
    const double x = 1e10;
    const Polygon wall = {{x - 1, -10}, {x, -10}, {x, 10}, {x - 1, 10}};
    for (const auto& [gap, expected] : {std::pair(0x1p-31, 1u), std::pair(0x1p-29, 2u)}) {
        const Polygon body = {{x, 0.5}, {x + 1, 0}, {x + 1, 1}, {x, 0.5 + gap}};
        EXPECT_EQ(find_contacts(body, {wall}).size(), expected) << gap;
    }
}

// Review-33: an obstacle whose edges are 2^-1000 long at a corner of a body whose edges are about
// 1: the corner on the tip gets one contact per tip edge (docs/formats.md), normals along
// (-1, 1) and (1, 1). The overlap check's walk along the body's edges through the tip's grid once
// cut them into pieces of the grid's cells, 2^1000 of them (a 2^-53 tip took 5 s and 336 MB), and
// the normal of an edge whose squared length underflows was refused as not finite.
TEST(FindContacts, TinyObstacleAtALargeCorner) {
    const double e = 0x1p-1000;
    const Polygon body = {{0, 0}, {1, 1}, {-1, 1}};
    const Polygon tip = {{0, 0}, {-e, -e}, {e, -e}};
    const std::vector<Contact> found = find_contacts(body, {tip});
    ASSERT_EQ(found.size(), 2u);
    EXPECT_EQ(std::abs(found[0].normal.x()), found[0].normal.y());
    EXPECT_EQ(std::abs(found[1].normal.x()), found[1].normal.y());
    EXPECT_EQ(found[0].normal.x(), -found[1].normal.x());
}

TEST(SceneJson, WrittenScenesReadBackUnchanged) {
    std::ifstream in(std::string(MOMENTLAB_EXAMPLES) + "/figure-4-peg-in-hole.json");
    std::ostringstream text;
    text << in.rdbuf();
    const Scene a = read_scene_text(text.str());
    const Scene b = read_scene(to_json(a));
    ASSERT_EQ(b.contacts.size(), a.contacts.size());
    for (std::size_t j = 0; j < a.contacts.size(); ++j) {
        EXPECT_EQ(b.contacts[j].point, a.contacts[j].point);
        EXPECT_EQ(b.contacts[j].normal, a.contacts[j].normal);  // unit already: unchanged
        EXPECT_EQ(b.contacts[j].mu_kinetic, a.contacts[j].mu_kinetic);
        EXPECT_EQ(b.contacts[j].name, a.contacts[j].name);
    }
    EXPECT_EQ(b.body->inertia, a.body->inertia);
    EXPECT_EQ(b.body->polygon, a.body->polygon);
    EXPECT_EQ(b.obstacles.size(), a.obstacles.size());
}

}  // namespace
}  // namespace momentlab
