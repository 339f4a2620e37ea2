// Pushing (Mason 1991, section 3, Example 2, Figure 6): the 24 cases of the block along the
// wall against a table derived by hand, and every case of every bundled scene against forces
// sampled from the definition of the finger's force set.
#include <gtest/gtest.h>

#include "../common/examples.hpp"

#include <cmath>
#include <fstream>
#include <optional>
#include <random>
#include <sstream>

#include "momentlab/mechanics/analysis.hpp"
#include "momentlab/mechanics/margin.hpp"
#include "momentlab/planning/push.hpp"

namespace momentlab {
namespace {

const ModeForces& mode(const std::vector<ModeForces>& a, const std::string& letters) {
    for (const ModeForces& m : a) {
        if (m.mode.letters == letters) return m;
    }
    throw std::logic_error("no mode " + letters);
}

std::string trim(const std::string& s) {
    const auto b = s.find_first_not_of(' '), e = s.find_last_not_of(' ');
    return b == std::string::npos ? "" : s.substr(b, e - b + 1);
}

std::vector<std::string> split(const std::string& line) {
    std::vector<std::string> out;
    std::istringstream in(line);
    for (std::string field; std::getline(in, field, '|');) out.push_back(trim(field));
    return out;
}

std::vector<double> numbers(const std::string& s) {
    std::vector<double> out;
    if (s == "-") return out;
    std::istringstream in(s);
    for (double x; in >> x;) out.push_back(x);
    return out;
}

// The finger's edge cones: n = (1, 0) into the body, t = (n.y, -n.x) = (0, -1). Slip l: the body
// slides along -t (up) past the finger, so friction on it acts along +t (down): n + mu t =
// (1, -1/2). Slip r: n - mu t = (1, 1/2). Slip f: either, and everything between.
TEST(Push, EdgeActionsAreTheSlipEdgesAtBothEnds) {
    const Cone l = push_actions(Vec2(0, 0), Vec2(0, 0.5), Vec2(1, 0), contact_mode('l'), 0.5);
    EXPECT_TRUE(l.has(wrench_at(Vec2(0, 0.25), Vec2(1, -0.5))));
    EXPECT_FALSE(l.has(wrench_at(Vec2(0, 0.25), Vec2(1, 0.5))));
    const Cone r = push_actions(Vec2(0, 0), Vec2(0, 0.5), Vec2(1, 0), contact_mode('r'), 0.5);
    EXPECT_TRUE(r.has(wrench_at(Vec2(0, 0.25), Vec2(1, 0.5))));
    const Cone f = push_actions(Vec2(0, 0), Vec2(0, 0.5), Vec2(1, 0), contact_mode('f'), 0.5);
    EXPECT_TRUE(f.has(wrench_at(Vec2(0, 0.1), Vec2(1, 0.5))));
    EXPECT_TRUE(f.has(wrench_at(Vec2(0, 0.4), Vec2(1, -0.5))));
    EXPECT_TRUE(f.has(wrench_at(Vec2(0, 0.4), Vec2(1, 0))));
    EXPECT_FALSE(f.has(wrench_at(Vec2(0, 0.6), Vec2(1, 0))));  // beyond the edge
    EXPECT_THROW((void)contact_mode('x'), std::invalid_argument);
}

// The golden table (tests/planning/golden/push-block-along-wall-rr.txt) was derived by hand in
// docs/planning.md; every row is checked: verdict, obstruction, touch segment and directions.
TEST(Push, BlockAlongTheWallMatchesTheTwentyFourCasesDerivedByHand) {
    const Scene scene = testing::example_scene("figure-3-block-along-wall.json");
    const std::vector<PushCase> cases = plan_push(scene, mode(analyze(scene), "rr"), PushOptions{Rational(0.5), false});
    std::ifstream in(MOMENTLAB_GOLDEN "/push-block-along-wall-rr.txt");
    ASSERT_TRUE(in) << "golden file missing";
    std::size_t k = 0;
    for (std::string line; std::getline(in, line);) {
        if (line.empty() || line[0] == '#') continue;
        const std::vector<std::string> f = split(line);
        ASSERT_EQ(f.size(), 7u) << line;
        ASSERT_LT(k, cases.size());
        const PushCase& c = cases[k++];
        SCOPED_TRACE(line);
        EXPECT_EQ(c.feature.name(), f[0]);
        EXPECT_EQ(std::string(1, letter(c.slip)), f[1]);
        EXPECT_EQ(to_string(c.verdict), f[2]);
        EXPECT_EQ(c.blocked, f[3]);
        const std::vector<double> touch = numbers(f[4]), dirs = numbers(f[5]);
        if (touch.empty()) {
            EXPECT_TRUE(c.touch.empty());
        } else {
            ASSERT_EQ(c.touch.size(), 1u);
            EXPECT_NEAR(c.touch[0].first.x(), touch[0], 1e-12);
            EXPECT_NEAR(c.touch[0].first.y(), touch[1], 1e-12);
            EXPECT_NEAR(c.touch[0].second.x(), touch[2], 1e-12);
            EXPECT_NEAR(c.touch[0].second.y(), touch[3], 1e-12);
        }
        if (dirs.empty()) {
            EXPECT_FALSE(c.directions.has_value());
        } else {
            ASSERT_TRUE(c.directions.has_value());
            EXPECT_NEAR(c.directions->from, dirs[0], 1e-12);
            EXPECT_NEAR(c.directions->to, dirs[1], 1e-12);
        }
    }
    EXPECT_EQ(k, 24u);
    EXPECT_EQ(cases.size(), 24u);
}

TEST(Push, IgnoringInterferenceChangesNoVerdictOfTheBlockButMarksIt) {
    const Scene scene = testing::example_scene("figure-3-block-along-wall.json");
    const auto analysis = analyze(scene);
    const auto& rr = mode(analysis, "rr");
    const auto with = plan_push(scene, rr, PushOptions{Rational(0.5), false});
    const auto without = plan_push(scene, rr, PushOptions{Rational(0.5), true});
    ASSERT_EQ(with.size(), without.size());
    for (std::size_t i = 0; i < with.size(); ++i) {
        EXPECT_EQ(with[i].verdict, without[i].verdict) << with[i].feature.name() << " " << letter(with[i].slip);
        EXPECT_EQ(without[i].blocked, "ignored");
    }
}

// A second obstacle against the trailing edge up to height h. With h = 1/2 it covers the edge
// and its outboard vertex: those solutions remain, but blocked. With h = 3/10 the finger may
// still touch the edge above it: the touch interval is [3/16, 1/2] (by hand) cut to [3/10, 1/2].
TEST(Push, ObstaclesBlockSolutionsOrShortenTheTouchInterval) {
    Scene scene = testing::example_scene("figure-3-block-along-wall.json");
    const auto analysis = analyze(scene);
    const auto& rr = mode(analysis, "rr");
    const auto find = [](const std::vector<PushCase>& cases, const std::string& feature, char slip) {
        for (const PushCase& c : cases) {
            if (c.feature.name() == feature && letter(c.slip) == slip) return c;
        }
        throw std::logic_error("no case");
    };
    scene.obstacles.push_back({{-1, 0}, {0, 0}, {0, 0.5}, {-1, 0.5}});
    auto cases = plan_push(scene, rr, PushOptions{Rational(0.5), false});
    EXPECT_EQ(find(cases, "edge 3", 'l').verdict, PushVerdict::Blocked);
    EXPECT_EQ(find(cases, "edge 3", 'l').blocked, "all");
    EXPECT_EQ(find(cases, "vertex 3", 'f').verdict, PushVerdict::Blocked);
    EXPECT_EQ(find(cases, "edge 3", 'r').verdict, PushVerdict::Infeasible);  // no solutions at all
    EXPECT_EQ(std::count_if(cases.begin(), cases.end(), [](const PushCase& c) { return c.feasible(); }), 0);

    scene.obstacles.back() = {{-1, 0}, {0, 0}, {0, 0.3}, {-1, 0.3}};
    cases = plan_push(scene, rr, PushOptions{Rational(0.5), false});
    const PushCase l = find(cases, "edge 3", 'l');
    EXPECT_EQ(l.verdict, PushVerdict::Feasible);
    EXPECT_EQ(l.blocked, "part");
    ASSERT_EQ(l.touch.size(), 1u);
    EXPECT_NEAR(l.touch[0].first.y(), 0.5, 1e-12);
    EXPECT_NEAR(l.touch[0].second.y(), 0.3, 1e-12);
    ASSERT_TRUE(l.best.has_value());
    EXPECT_GT(l.best->point.y(), 0.3);
    EXPECT_EQ(find(cases, "vertex 3", 'l').verdict, PushVerdict::Feasible);
}

// The same block listed clockwise: the same features (as point sets) get the same verdicts.
TEST(Push, OrientationOfTheOutlineDoesNotMatter) {
    const Scene scene = testing::example_scene("figure-3-block-along-wall.json");
    Scene reversed = scene;
    std::reverse(reversed.body->polygon.begin(), reversed.body->polygon.end());
    const auto analysis = analyze(scene);
    const auto& rr = mode(analysis, "rr");
    const auto a = plan_push(scene, rr), b = plan_push(reversed, rr);
    ASSERT_EQ(a.size(), b.size());
    const auto key = [](const PushCase& c) {
        Vec2 p = c.feature.from, q = c.feature.to;
        if (q.x() < p.x() || (q.x() == p.x() && q.y() < p.y())) std::swap(p, q);
        std::ostringstream s;
        s << p.transpose() << " " << q.transpose() << " " << letter(c.slip);
        return s.str();
    };
    std::map<std::string, PushVerdict> verdicts;
    for (const PushCase& c : a) verdicts[key(c)] = c.verdict;
    for (const PushCase& c : b) {
        ASSERT_TRUE(verdicts.count(key(c))) << key(c);
        EXPECT_EQ(verdicts[key(c)], c.verdict) << key(c);
    }
}

// Issue 44, item 8: one feature and slip asked for (PushOptions::feature, slip) is solved alone
// and is exactly the case of the whole table, on a body with a notch (reflex vertex) under
// gravity and obstacles; a wrong index or the slip s is refused. What the selector saves (one
// case of a 10^5-gon in the time and memory of the analysis) is measured by make large-inputs.
TEST(Push, OneCaseAskedForIsTheTablesCase) {
    Scene scene = testing::example_scene("figure-3-block-along-wall.json");
    scene.body->polygon = {{0, 0}, {1, 0}, {1, 0.25}, {0.5, 0.25}, {0.5, 0.5}, {0, 0.5}};
    const auto analysis = analyze(scene);
    const ModeForces& rr = mode(analysis, "rr");
    const std::size_t n = scene.body->polygon.size();
    for (const bool with_modes : {false, true}) {
        PlanContext context;
        if (with_modes) context.modes = analysis;
        const PushOptions all{Rational(0.5), false};
        const std::vector<PushCase> table = plan_push(scene, rr, all, context);
        ASSERT_EQ(table.size(), 6 * n);
        std::vector<PushCase> streamed;
        plan_push(scene, rr, all, context, [&](PushCase&& c) { streamed.push_back(std::move(c)); });
        ASSERT_EQ(streamed.size(), table.size());
        for (const PushCase& c : table) {
            PushOptions one = all;
            one.feature = PushFeatureId{c.feature.kind, c.feature.index};
            one.slip = c.slip;
            const std::vector<PushCase> got = plan_push(scene, rr, one, context);
            ASSERT_EQ(got.size(), 1u);
            const PushCase& g = got[0];
            SCOPED_TRACE(c.feature.name() + " slip " + letter(c.slip));
            EXPECT_EQ(g.feature.name(), c.feature.name());
            EXPECT_EQ(g.slip, c.slip);
            EXPECT_EQ(g.verdict, c.verdict);
            EXPECT_EQ(g.feature.reflex, c.feature.reflex);
            EXPECT_EQ(g.touch, c.touch);
            EXPECT_EQ(g.directions.has_value(), c.directions.has_value());
            if (g.directions && c.directions) {
                EXPECT_EQ(g.directions->from, c.directions->from);
                EXPECT_EQ(g.directions->to, c.directions->to);
            }
            EXPECT_EQ(g.best.has_value(), c.best.has_value());
            if (g.best && c.best) {
                EXPECT_EQ(g.best->point, c.best->point);
                EXPECT_EQ(g.best->direction, c.best->direction);
            }
            EXPECT_EQ(g.unique, c.unique);
            EXPECT_EQ(g.shared, c.shared);
            EXPECT_EQ(g.best_unique, c.best_unique);
            const std::size_t k = static_cast<std::size_t>(&c - table.data());
            EXPECT_EQ(streamed[k].feature.name(), c.feature.name());
            EXPECT_EQ(streamed[k].verdict, c.verdict);
        }
        // A feature alone: its three slips, l, f, r, in the table's order.
        PushOptions vertex = all;
        vertex.feature = PushFeatureId{PushFeature::Kind::Vertex, 3};
        const std::vector<PushCase> three = plan_push(scene, rr, vertex, context);
        ASSERT_EQ(three.size(), 3u);
        for (std::size_t k = 0; k < 3; ++k) EXPECT_EQ(three[k].verdict, table[3 * (n + 3) + k].verdict);
    }
    PushOptions bad{Rational(0.5), false};
    bad.feature = PushFeatureId{PushFeature::Kind::Edge, n};
    EXPECT_THROW((void)plan_push(scene, rr, bad), std::invalid_argument);
    bad.feature.reset();
    bad.slip = ContactMode::Separating;
    EXPECT_THROW((void)plan_push(scene, rr, bad), std::invalid_argument);
}

// The best push of a case lies deep in the goal's unique set: at least half as far from every
// boundary (query's margins) as the deepest of the pushes sampled on the edge, within the
// finger's cone (slip f) or along the best's own direction (a sliding finger's one direction),
// that give the goal alone. Before, the mean of one unique part's raw generators was taken: on
// the block along the wall three of the five best pushes sat within 1e-4 of another mode.
TEST(Push, BestPushIsDeepInTheGoalsUniqueSet) {
    const Scene scene = testing::example_scene("figure-3-block-along-wall.json");
    const auto analysis = analyze(scene);
    const ModeForces& rr = mode(analysis, "rr");
    PlanContext context;
    context.modes = analysis;
    context.metric = default_metric(scene);
    const double mu = 0.5;
    const auto depth = [&](const Vec2& point, const Vec2& direction) -> std::optional<double> {
        const Vec3 w(direction.x(), direction.y(), point.x() * direction.y() - point.y() * direction.x());
        for (const ModeForces& m : analysis) {
            if (m.mode.letters != "rr" && m.applied.has(w)) return std::nullopt;
        }
        if (!rr.applied.in_relative_interior(w)) return std::nullopt;
        const QueryMargins q = margins_of(analysis, wrench_through(exact(point), exact(direction)), *context.metric);
        double d = q.to_other.value_or(INFINITY);
        for (const double inside : q.inside) d = std::min(d, inside);
        return d;
    };
    int checked = 0;
    for (const PushCase& c : plan_push(scene, rr, PushOptions{Rational(mu), false}, context)) {
        if (c.verdict != PushVerdict::Feasible || !c.best_unique || c.feature.kind != PushFeature::Kind::Edge) continue;
        SCOPED_TRACE(c.feature.name() + " slip " + letter(c.slip));
        const std::optional<double> best = depth(c.best->point, c.best->direction);
        ASSERT_TRUE(best.has_value());
        double deepest = 0.0;
        const double spread = c.slip == ContactMode::Fixed ? std::atan(mu) : 0.0;
        const double base = std::atan2(c.best->direction.y(), c.best->direction.x());
        const double normal = std::atan2(c.feature.normal.y(), c.feature.normal.x());
        for (int i = 0; i <= 100; ++i) {
            const Vec2 point = c.feature.from + (i / 100.0) * (c.feature.to - c.feature.from);
            for (int j = -20; j <= 20; ++j) {
                const double angle = spread > 0 ? normal + spread * j / 20.0 : base;
                if (const auto d = depth(point, Vec2(std::cos(angle), std::sin(angle)))) deepest = std::max(deepest, *d);
                if (spread == 0) break;
            }
        }
        EXPECT_GT(deepest, 0.0);
        EXPECT_GE(*best, 0.5 * deepest) << "best " << *best << ", deepest sampled " << deepest;
        ++checked;
    }
    EXPECT_GE(checked, 2);  // edge 3 with slip l and f
}

// One case asked for costs one case (issue 44, item 8: on a 10^5-gon one case took 19.5 s and
// 1.64 GB, the whole table's 6 n cases solved and all but one dropped): counted by the planner
// itself, so the test fails however the others would be solved and dropped.
TEST(Push, OneCaseAskedForSolvesOneCase) {
    Scene scene = testing::example_scene("figure-3-block-along-wall.json");
    const std::size_t n = 1000;
    scene.body->polygon.clear();
    for (std::size_t k = 0; k < n; ++k) {
        const double angle = 2 * M_PI * static_cast<double>(k) / static_cast<double>(n);
        scene.body->polygon.emplace_back(0.5 + 0.5 * std::cos(angle), 0.5 + 0.5 * std::sin(angle));
    }
    scene.obstacles.clear();
    const auto analysis = analyze(scene);
    PlanContext context;
    context.modes = analysis;
    const ModeForces& goal = analysis.front();
    const auto solved = [&](const PushOptions& options) {
        const std::size_t before = push_cases_solved();
        std::size_t given = 0;
        plan_push(scene, goal, options, context, [&](PushCase&&) { ++given; });
        EXPECT_EQ(given, push_cases_solved() - before);
        return push_cases_solved() - before;
    };
    PushOptions one{Rational(0.5), false, PushFeatureId{PushFeature::Kind::Vertex, 5}, ContactMode::Fixed};
    EXPECT_EQ(solved(one), 1u);
    one.feature = PushFeatureId{PushFeature::Kind::Edge, n - 1};
    EXPECT_EQ(solved(one), 1u);
    one.slip.reset();
    EXPECT_EQ(solved(one), 3u);
    one.feature.reset();
    one.slip = ContactMode::SlidingLeft;
    EXPECT_EQ(solved(one), 2 * n);
    EXPECT_EQ(solved(PushOptions{}), 6 * n);
}

// An L-shaped body: its notch vertex is reported as such for sliding fingers, and a finger
// stuck in the notch pushes with both edges' friction cones.
TEST(Push, NotchVerticesAreReportedAndAStuckFingerUsesBothEdges) {
    Scene scene = testing::example_scene("figure-3-block-along-wall.json");
    scene.body->polygon = {{0, 0}, {1, 0}, {1, 0.25}, {0.5, 0.25}, {0.5, 0.5}, {0, 0.5}};
    const auto cases = plan_push(scene, mode(analyze(scene), "rr"));
    ASSERT_EQ(cases.size(), 36u);
    int reflex = 0;
    for (const PushCase& c : cases) {
        const bool notch = c.feature.kind == PushFeature::Kind::Vertex && c.feature.index == 3;
        EXPECT_EQ(c.feature.reflex, notch) << c.feature.name();
        if (notch && letter(c.slip) != 'f') {
            EXPECT_EQ(c.verdict, PushVerdict::Reflex);
            ++reflex;
        }
        if (notch && letter(c.slip) == 'f') {
            // At (1/2, 1/4) the edges' inward normals are (0, -1) and (-1, 0); with mu = 1/2
            // the two cones together span the directions clockwise from (1/2, -1) to (-1, 1/2).
            ASSERT_EQ(c.pieces.size(), 1u);
            const Cone& w = c.pieces[0].actions;
            const Vec2 v(0.5, 0.25);
            EXPECT_TRUE(w.has(wrench_at(v, Vec2(0.5, -1))));
            EXPECT_TRUE(w.has(wrench_at(v, Vec2(-1, 0.5))));
            EXPECT_TRUE(w.has(wrench_at(v, Vec2(-1, -1))));
            EXPECT_FALSE(w.has(wrench_at(v, Vec2(1, -1))));
            EXPECT_FALSE(w.has(wrench_at(v, Vec2(0.5, 1))));
        }
    }
    EXPECT_EQ(reflex, 2);
}

// --- Every case against pushes sampled from the definition ------------------------------------

// Pushes of one case drawn from the definition: a point of the feature and a finger normal n in
// its range (an edge's normal; at a convex vertex any direction between its edges' normals),
// then the force n + mu t (l), n - mu t (r) or n + s t, |s| <= mu (f), t = (n.y, -n.x).
std::vector<Vec3> sample_pushes(const Polygon& ccw, std::size_t index, bool vertex, char slip, double mu,
                                std::mt19937& rng, int count) {
    const std::size_t n = ccw.size();
    const auto inward = [&](std::size_t i) {
        const Vec2 d = ccw[(i + 1) % n] - ccw[i];
        return Vec2(-d.y(), d.x()).normalized();
    };
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::vector<Vec3> out;
    for (int k = 0; k < count; ++k) {
        Vec2 p, normal;
        if (!vertex) {
            p = ccw[index] + u(rng) * (ccw[(index + 1) % n] - ccw[index]);
            normal = inward(index);
        } else {
            p = ccw[index];
            const Vec2 a = inward((index + n - 1) % n), b = inward(index);
            const double from = std::atan2(a.y(), a.x());
            const double width = std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b));  // in [0, pi)
            const double phi = from + u(rng) * width;
            normal = Vec2(std::cos(phi), std::sin(phi));
        }
        const Vec2 t(normal.y(), -normal.x());
        const double s = slip == 'l' ? mu : slip == 'r' ? -mu : mu * (2.0 * u(rng) - 1.0);
        out.push_back(wrench_at(p, normal + s * t));
    }
    return out;
}

// w and its perturbations by 1e-9 |w| along each axis all lie in E (or in its interior): a
// verdict that holds for w then holds for the exact push it rounds, whatever the rounding of
// the sample's moment (pushes at a contact point lie exactly on a facet plane of E, where an
// unperturbed rounded sample lands on either side).
bool robustly_in(const Cone& e, const Vec3& w, bool interior) {
    const double delta = 1e-9 * w.norm();
    for (int k = 0; k < 7; ++k) {
        Vec3 x = w;
        if (k > 0) x[(k - 1) / 2] += (k % 2 ? delta : -delta);
        if (interior ? !(e.dimension() == 3 && e.in_relative_interior(x)) : !e.has(x)) return false;
    }
    return true;
}

Scene sharp_wedge() {
    // A needle-like triangle (dyadic, so exact end to end): the vertex at (2, 0) is about 7.1
    // degrees wide, so a sticking finger's arc there (172.9 + 2 atan(1/2) degrees) exceeds pi and
    // is split in two.
    Scene s;
    s.body = Body{1.0, Vec2(0.625, 0.125), 0.375, {{0, 0}, {2, 0}, {0, 0.25}}};
    s.contacts = {Contact::make(Vec2(0, 0), Vec2(0, 1), 0.5), Contact::make(Vec2(2, 0), Vec2(0, 1), 0.5)};
    return s;
}

TEST(Push, EveryCaseAgreesWithPushesSampledFromTheDefinition) {
    std::vector<std::pair<std::string, Scene>> scenes;
    for (const char* name : {"figure-3-block-along-wall.json", "figure-4-peg-in-hole.json", "rod-in-corner.json",
                             "block-on-table.json"}) {
        scenes.emplace_back(name, testing::example_scene(name));
    }
    scenes.emplace_back("sharp wedge", sharp_wedge());
    std::mt19937 rng(20261121);
    int feasible = 0, checked = 0, split = 0;
    for (const auto& [name, scene] : scenes) {
        Polygon ccw = scene.body->polygon;
        double area2 = 0;
        for (std::size_t i = 0; i < ccw.size(); ++i) area2 += ccw[i].x() * ccw[(i + 1) % ccw.size()].y() - ccw[(i + 1) % ccw.size()].x() * ccw[i].y();
        const bool reversed = area2 < 0;
        if (reversed) std::reverse(ccw.begin(), ccw.end());
        for (const double mu : {0.0, 0.5, 1.5}) {
            for (const ModeForces& goal : analyze(scene)) {
                const Cone& e = goal.applied;
                for (const PushCase& c : plan_push(scene, goal, PushOptions{Rational(mu), true})) {
                    SCOPED_TRACE(name + " mode " + goal.mode.letters + " " + c.feature.name() + " slip " + letter(c.slip) +
                                 " mu " + std::to_string(mu));
                    if (c.feature.reflex) continue;
                    const std::size_t n = ccw.size();
                    const bool vertex = c.feature.kind == PushFeature::Kind::Vertex;
                    // The same feature in the counter-clockwise copy.
                    const std::size_t index = !reversed ? c.feature.index
                                              : vertex  ? n - 1 - c.feature.index
                                                        : (2 * n - 2 - c.feature.index) % n;
                    bool in_e = false, in_interior = false;
                    for (const Vec3& w : sample_pushes(ccw, index, vertex, letter(c.slip), mu, rng, 150)) {
                        in_e = in_e || robustly_in(e, w, false);
                        in_interior = in_interior || robustly_in(e, w, true);
                    }
                    if (in_interior) { EXPECT_EQ(c.verdict, PushVerdict::Feasible); }
                    if (in_e) { EXPECT_NE(c.verdict, PushVerdict::Infeasible); }
                    if (c.verdict == PushVerdict::Infeasible) { EXPECT_FALSE(in_e); }
                    split += c.pieces.size() == 2;
                    ++checked;
                    if (c.verdict != PushVerdict::Feasible) continue;
                    ++feasible;
                    // The representative push lies inside E, on the feature, within the slip's range.
                    ASSERT_TRUE(c.best.has_value());
                    EXPECT_TRUE(e.in_relative_interior(c.best->wrench()));
                    // W holds the push up to rounding (for sliding fingers W is a plane fan, which a
                    // rounded wrench misses): its point is on the feature and its direction is a
                    // finger normal of the feature turned by the slip's friction angle.
                    const Vec2 a = ccw[index], b = ccw[(index + 1) % n], p = c.best->point;
                    if (vertex) {
                        EXPECT_EQ(p, a);
                    } else {
                        EXPECT_NEAR((p - a).x() * (b - a).y() - (p - a).y() * (b - a).x(), 0.0, 1e-12);
                        EXPECT_LE((p - a).dot(b - a), (b - a).squaredNorm() * (1 + 1e-12));
                        EXPECT_GE((p - a).dot(b - a), -1e-12);
                    }
                    const auto inward = [&](std::size_t i) {
                        const Vec2 d = ccw[(i + 1) % n] - ccw[i];
                        return Vec2(-d.y(), d.x()).normalized();
                    };
                    const Vec2 first = vertex ? inward((index + n - 1) % n) : inward(index);
                    const Vec2 last = inward(index);
                    const double width = std::atan2(first.x() * last.y() - first.y() * last.x(), first.dot(last));
                    const double middle = std::atan2(first.y(), first.x()) + width / 2;
                    const double friction = std::atan(mu);
                    const double offset = letter(c.slip) == 'l' ? -friction : letter(c.slip) == 'r' ? friction : 0.0;
                    const double spread = letter(c.slip) == 'f' ? friction : 0.0;
                    const Vec2 d = c.best->direction;
                    const double rel = std::remainder(std::atan2(d.y(), d.x()) - middle - offset, 2 * M_PI);
                    EXPECT_LE(std::abs(rel), width / 2 + spread + 1e-12);
                }
            }
        }
    }
    EXPECT_GT(feasible, 20);
    EXPECT_GT(split, 0);
    EXPECT_GT(checked, 500);
}

}  // namespace
}  // namespace momentlab
