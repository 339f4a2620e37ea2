// Margins of a question (mechanics/margin.hpp): by hand on the block along the wall, and on
// random scenes against an oracle that shares no code with the library (the modes' E in exact
// rationals from the scene's raw numbers by cddlib; membership by the exact LP): every margin is
// the oracle's distance, and tight: a move of 0.999 times it keeps the answer, 1.001 times (towards
// the nearest facet or set) changes it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <random>
#include <set>

#include "../common/examples.hpp"
#include "../common/scenes.hpp"
#include "../common/sizes.hpp"
#include "cdd_oracle.hpp"
#include "mode_oracle.hpp"
#include "momentlab/mechanics/advanced.hpp"
#include "momentlab/mechanics/margin.hpp"

namespace momentlab {
namespace {

using reference::QVec;

// The block along the wall (contacts (0, 0), (1, 0), mu 1/2, centre of mass (1/2, 1/4)): a force
// (fx, fy) through the centre of mass slides it (rr) while fx >= -fy / 2 and rests (ff) while
// |fx| <= -fy / 2, so (1, -1) is 1/2 / |(1, 1/2)| = 1/sqrt(5) from the line fx + fy / 2 = 0 between
// them, and gravity (0, -1) is as far from each of ff's friction lines (torques about the centre
// of mass are 0 along that whole line, so the scaled torque does not enter).
TEST(Margin, BlockAlongTheWallByHand) {
    const Scene scene = testing::example_scene("figure-3-block-along-wall.json");
    const auto analysis = analyze(scene);
    const WrenchMetric metric = default_metric(scene);
    EXPECT_EQ(metric.reference, Vec2(0.5, 0.25));
    EXPECT_DOUBLE_EQ(metric.length, std::sqrt(0.3125));  // (1/2, 1/4) to either contact
    for (const Vec3& e : {Vec3(1, -1, -0.75), Vec3(0, -1, -0.5)}) {
        const QueryResult r = query(analysis, e);
        ASSERT_EQ(r.modes.size(), 1u);
        const QueryMargins m = query_margins(analysis, r.modes, e, metric);
        EXPECT_NEAR(m.inside[0], 1.0 / std::sqrt(5.0), 1e-15) << e.transpose();
        ASSERT_TRUE(m.to_other);
        EXPECT_NEAR(*m.to_other, 1.0 / std::sqrt(5.0), 1e-15) << e.transpose();
    }
}

// E of a mode from the scene's raw numbers, by cddlib in exact rationals: the closure A of the
// mode's twists (its equations and inequalities in N_j, T_j), converted to generators; E is the
// cone of M times those and of the negated contact generators (M = 0 quasi-statically).
oracle::OracleCone exact_applied_set(const Scene& scene, const std::string& letters) {
    const testing::ExactContacts c(scene.contacts);
    std::vector<QVec> halfspaces;
    for (std::size_t j = 0; j < letters.size(); ++j) {
        halfspaces.push_back(c.n[j]);
        if (letters[j] == 's') continue;
        halfspaces.push_back(reference::neg(c.n[j]));
        if (letters[j] != 'l') halfspaces.push_back(c.t[j]);
        if (letters[j] != 'r') halfspaces.push_back(reference::neg(c.t[j]));
    }
    const oracle::OracleCone a = oracle::from_halfspaces(halfspaces);
    const reference::QMat m = reference::inertia(*scene.body);
    std::vector<QVec> generators;
    for (const QVec& r : a.rays) generators.push_back(reference::mul(m, r));
    for (const QVec& l : a.lineality) {
        generators.push_back(reference::mul(m, l));
        generators.push_back(reference::neg(reference::mul(m, l)));
    }
    for (std::size_t j = 0; j < letters.size(); ++j) {
        for (const QVec& g : c.raw[j].generators(letters[j])) generators.push_back(reference::neg(g));
    }
    return oracle::from_generators(generators);
}

Vec3 rounded(const QVec& v) { return reference::to_vec3(v); }

// The metric of docs/design.md ("Margins"), from the scene: torques about the centre of mass,
// divided by the largest distance of a contact from it.
struct Metric {
    Vec2 r;
    double length;
    explicit Metric(const Scene& scene) : r(scene.body->com), length(0.0) {
        for (const Contact& c : scene.contacts) length = std::max(length, (c.point - r).norm());
    }
    [[nodiscard]] Vec3 scaled(const Vec3& w) const {
        return Vec3(w.x(), w.y(), (w.z() - (r.x() * w.y() - r.y() * w.x())) / length);
    }
    [[nodiscard]] Vec3 unscaled(const Vec3& p) const {
        return Vec3(p.x(), p.y(), length * p.z() + r.x() * p.y() - r.y() * p.x());
    }
    // A plane h . w = 0 of wrench space as the unit normal of its image in the scaled space.
    [[nodiscard]] Vec3 normal(const QVec& h) const {
        const Vec3 v = rounded(h);
        return Vec3(v.x() - r.y() * v.z(), v.y() + r.x() * v.z(), length * v.z()).normalized();
    }
};

// The nearest point to p (scaled) of a cone given exactly: p itself when inside, else the best of
// the projections onto the spans of the lineality with at most two extreme rays that land in the
// cone (the nearest point lies in the relative interior of a face, spanned so).
Vec3 nearest_point(const oracle::OracleCone& cone, const Metric& m, const Vec3& p) {
    const auto inside = [&](const Vec3& x) {
        for (const QVec& f : cone.facets) {
            if (m.normal(f).dot(x) < -1e-12 * (1 + x.norm())) return false;
        }
        for (const QVec& f : cone.equations) {
            if (std::abs(m.normal(f).dot(x)) > 1e-12 * (1 + x.norm())) return false;
        }
        return true;
    };
    if (inside(p)) return p;
    std::vector<Vec3> rays;
    for (const QVec& r : cone.rays) rays.push_back(m.scaled(rounded(r)).normalized());
    Vec3 best = Vec3::Zero();
    const auto project = [&](std::vector<Vec3> span) {
        for (const QVec& l : cone.lineality) span.push_back(m.scaled(rounded(l)));
        std::vector<Vec3> basis;  // Gram-Schmidt
        for (const Vec3& v : span) {
            Vec3 u = v;
            for (const Vec3& b : basis) u -= u.dot(b) * b;
            if (u.norm() > 1e-9 * v.norm()) basis.push_back(u.normalized());
        }
        Vec3 q = Vec3::Zero();
        for (const Vec3& b : basis) q += p.dot(b) * b;
        if (inside(q) && (q - p).norm() < (best - p).norm()) best = q;
    };
    project({});
    for (std::size_t i = 0; i < rays.size(); ++i) {
        project({rays[i]});
        for (std::size_t j = i + 1; j < rays.size(); ++j) project({rays[i], rays[j]});
    }
    return best;
}

// On random scenes (the slanted families, up to 3 contacts) and random wrenches: each margin that
// query_margins gives equals the oracle's distance (E from cddlib in exact rationals, the distance
// to its nearest facet plane, or to its nearest point for a mode that does not hold the wrench),
// and is tight, decided by the exact LP on the wrenches moved in doubles: moved 0.999 times the
// margin towards that facet (or that point) the answer is the same; 1.001 times, the mode is
// left (or, for a full-dimensional other E, entered). Two random moves of 0.999 times the least
// margin keep the whole answer. Margins under 1e-9 (relative) are counted, not moved.
TEST(Margin, MarginsAreTheOraclesDistancesAndTight) {
    testing::Random rnd(31);
    std::mt19937_64 rng(8);
    std::normal_distribution<double> normal;
    int compared = 0, tight_inside = 0, tight_other = 0, kept = 0, small = 0, other_flat = 0;
    for (int s = 0; s < testing::sized(40); ++s) {
        const Scene scene = testing::random_scene(rnd, static_cast<testing::SceneFamily>(s % 5), 3, false);
        const Metric metric(scene);
        const auto analysis = analyze(scene);
        const std::set<std::string> modes = testing::exact_modes(scene.contacts);
        std::map<std::string, oracle::OracleCone> sets;
        for (const std::string& letters : modes) sets.emplace(letters, exact_applied_set(scene, letters));
        const WrenchMetric library_metric = default_metric(scene);
        ASSERT_EQ(library_metric.reference, metric.r);
        ASSERT_DOUBLE_EQ(library_metric.length, metric.length);
        const auto answer = [&](const Vec3& e) { return testing::exact_answer(scene, modes, reference::q(e), false); };
        for (int w = 0; w < 4; ++w) {
            const Vec3 e = rnd.vec3(4.0);
            const std::vector<std::string> holding = answer(e);
            const QueryResult r = query(analysis, e);
            ASSERT_EQ(r.modes.size(), holding.size()) << "scene " << s;
            const QueryMargins margins = query_margins(analysis, r.modes, e, library_metric);
            const Vec3 p = metric.scaled(e);
            const auto moved = [&](const Vec3& direction, double t) -> Vec3 { return e + metric.unscaled(direction * t); };
            double least = std::numeric_limits<double>::infinity();
            for (std::size_t k = 0; k < r.modes.size(); ++k) {
                const std::string& letters = analysis[r.modes[k]].mode.letters;
                ASSERT_NE(std::find(holding.begin(), holding.end(), letters), holding.end()) << "scene " << s << " mode " << letters;
                const oracle::OracleCone& cone = sets.at(letters);
                // The distance to the boundary: 0 for a set that is not full-dimensional.
                double d = cone.dimension < 3 ? 0.0 : std::numeric_limits<double>::infinity();
                Vec3 towards = Vec3::Zero();
                for (const QVec& f : cone.facets) {
                    const Vec3 n = metric.normal(f);
                    if (cone.dimension == 3 && n.dot(p) < d) d = n.dot(p), towards = -n;
                }
                ++compared;
                if (!std::isfinite(d)) {  // E = R^3
                    EXPECT_EQ(margins.inside[k], d) << "scene " << s << " mode " << letters;
                    continue;
                }
                EXPECT_NEAR(margins.inside[k], d, 1e-9 * (1 + d)) << "scene " << s << " mode " << letters;
                least = std::min(least, d);
                if (d < 1e-9 * p.norm()) {
                    ++small;
                    continue;
                }
                const auto in = [&](const Vec3& x) { return testing::exact_lp_applied_in_mode(scene, letters, reference::q(x)); };
                EXPECT_TRUE(in(moved(towards, 0.999 * d))) << "scene " << s << " mode " << letters;
                EXPECT_FALSE(in(moved(towards, 1.001 * d))) << "scene " << s << " mode " << letters << " e " << e.transpose() << " d " << d
                                                           << " towards " << towards.transpose() << " moved " << moved(towards, 1.001 * d).transpose()
                                                           << " facets " << cone.facets.size() << " rays " << cone.rays.size()
                                                           << " lineality " << cone.lineality.size();
                ++tight_inside;
            }
            // The nearest set of a mode that does not hold e.
            std::optional<double> nearest;
            std::string which;
            Vec3 target = Vec3::Zero();
            for (const std::string& letters : modes) {
                if (std::find(holding.begin(), holding.end(), letters) != holding.end()) continue;
                const Vec3 q = nearest_point(sets.at(letters), metric, p);
                if (!nearest || (q - p).norm() < *nearest) nearest = (q - p).norm(), which = letters, target = q;
            }
            ASSERT_EQ(margins.to_other.has_value(), nearest.has_value()) << "scene " << s;
            if (nearest) {
                EXPECT_NEAR(*margins.to_other, *nearest, 1e-9 * (1 + *nearest)) << "scene " << s;
                ++compared;
                least = std::min(least, *nearest);
                const Vec3 towards = (target - p).normalized();
                const auto in = [&](const Vec3& x) { return testing::exact_lp_applied_in_mode(scene, which, reference::q(x)); };
                if (*nearest < 1e-9 * p.norm()) {
                    ++small;
                } else {
                    EXPECT_FALSE(in(moved(towards, 0.999 * *nearest))) << "scene " << s << " mode " << which;
                    if (sets.at(which).dimension == 3) {
                        EXPECT_TRUE(in(moved(towards, 1.001 * *nearest))) << "scene " << s << " mode " << which;
                        ++tight_other;
                    } else {
                        ++other_flat;  // a flat set: entered only at the point itself
                    }
                }
            }
            if (!std::isfinite(least) || least < 1e-9 * p.norm()) continue;
            for (int k = 0; k < 2; ++k) {
                const Vec3 d = Vec3(normal(rng), normal(rng), normal(rng)).normalized();
                EXPECT_EQ(answer(moved(d, 0.999 * least)), holding) << "scene " << s;
                ++kept;
            }
        }
    }
    std::cout << "[Margin] " << compared << " margins equal to the oracle's; tight: " << tight_inside << " inside, " << tight_other
              << " to another set (" << other_flat << " flat ones approached only); " << kept << " random moves kept the answer; "
              << small << " margins too small to move\n";
    EXPECT_GE(tight_inside, testing::floor_of(60));
    EXPECT_GE(tight_other, testing::floor_of(60));
    EXPECT_GE(kept, testing::floor_of(100));
}

}  // namespace
}  // namespace momentlab
