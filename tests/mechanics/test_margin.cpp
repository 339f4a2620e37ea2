// Margins of a question (mechanics/margin.hpp): by hand on the block along the wall, and on
// random scenes by their meaning, decided by exact membership (Cone::has), not by the distances:
// a wrench moved by less than its margin stays in each of its modes' sets and enters no other
// mode's set; moved a little more than its margin towards the nearest facet, it leaves.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "../common/examples.hpp"
#include "../common/scenes.hpp"
#include "../common/sizes.hpp"
#include "momentlab/mechanics/advanced.hpp"
#include "momentlab/mechanics/margin.hpp"

namespace momentlab {
namespace {

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

TEST(Margin, MovesSmallerThanTheMarginKeepTheAnswer) {
    testing::Random rnd(31);
    std::mt19937_64 rng(8);
    std::normal_distribution<double> normal;
    int checked = 0, left = 0;
    for (int s = 0; s < testing::sized(60); ++s) {
        const Scene scene = testing::random_scene(rnd, static_cast<testing::SceneFamily>(s % 5), 3, false);
        const auto analysis = analyze(scene);
        const WrenchMetric m = default_metric(scene);
        const auto unscale = [&](const Vec3& d) {  // S^-1: torque about the origin again
            return Vec3(d.x(), d.y(), m.length * d.z() + m.reference.x() * d.y() - m.reference.y() * d.x());
        };
        for (int w = 0; w < 20; ++w) {
            const Vec3 e = rnd.vec3(4.0);
            const QueryResult r = query(analysis, e);
            const QueryMargins margins = query_margins(analysis, r.modes, e, m);
            double keep = margins.to_other.value_or(1e300);
            for (double d : margins.inside) keep = std::min(keep, d);
            if (!(keep > 1e-9) || !std::isfinite(keep)) continue;
            for (int k = 0; k < 20; ++k) {
                const Vec3 d = Vec3(normal(rng), normal(rng), normal(rng)).normalized() * (0.999 * keep);
                const Vec3 moved = e + unscale(d);
                for (std::size_t i = 0; i < analysis.size(); ++i) {
                    const bool before = std::find(r.modes.begin(), r.modes.end(), i) != r.modes.end();
                    EXPECT_EQ(analysis[i].applied.has(moved), before) << "scene " << s << " mode " << analysis[i].mode.letters;
                }
                ++checked;
            }
            // Just past the nearest facet of a returned mode's set, the wrench is outside it.
            for (std::size_t k = 0; k < r.modes.size(); ++k) {
                const Cone& cone = analysis[r.modes[k]].applied;
                if (!(margins.inside[k] > 1e-9) || !std::isfinite(margins.inside[k])) continue;
                const Vec3 p = m.scaled(e);
                for (const ExactVector& f : cone.facets()) {
                    const Vec3 h = f.value();
                    const Vec3 n(h.x() - m.reference.y() * h.z(), h.y() + m.reference.x() * h.z(), m.length * h.z());
                    if (std::abs(n.dot(p) / n.norm() - margins.inside[k]) > 1e-12 * (1 + margins.inside[k])) continue;
                    const Vec3 out = e + unscale(-n.normalized() * (margins.inside[k] * 1.001 + 1e-9));
                    EXPECT_FALSE(cone.has(out)) << "scene " << s;
                    ++left;
                    break;
                }
            }
        }
    }
    std::cout << "[Margin] " << checked << " moves inside the margins, " << left << " just past one\n";
    EXPECT_GE(checked, testing::sized(10000));
    EXPECT_GE(left, testing::sized(300));
}

}  // namespace
}  // namespace momentlab
