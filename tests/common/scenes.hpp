#pragma once

// Random scenes with slanted normals in the families where rounding used to decide wrongly
// (normals through one point, parallel, on one line; far from the origin), and the exact
// transforms of a scene (dyadic translations, quarter turns, mirrors, scaling by powers of two,
// reordering contacts, scaling normals) with what each does to modes and wrenches.

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "momentlab/core/dyadic.hpp"
#include "momentlab/mechanics/scene.hpp"
#include "random_inputs.hpp"

namespace momentlab::testing {

/// The scene families of the exactness tests.
enum class SceneFamily { Concurrent, OnACircle, Parallel, Collinear, SlantedIntegers, GeneralDoubles };

inline const char* scene_family_name(SceneFamily f) {
    switch (f) {
        case SceneFamily::Concurrent: return "normals through one point";
        case SceneFamily::OnACircle: return "on a circle, normals through its centre";
        case SceneFamily::Parallel: return "parallel normals";
        case SceneFamily::Collinear: return "normals on one line";
        case SceneFamily::SlantedIntegers: return "slanted integer normals";
        default: return "general doubles";
    }
}

/// Small integer directions, most of them slanted.
inline Vec2 slanted_direction(Random& rnd) {
    static const Vec2 kDirections[] = {Vec2(3, 4), Vec2(-4, 3), Vec2(5, 12), Vec2(1, 2), Vec2(-2, 1),
                                       Vec2(2, 1), Vec2(1, -3), Vec2(-3, -4), Vec2(1, 1), Vec2(0, 1), Vec2(1, 0)};
    const Vec2 d = kDirections[rnd.integer(0, 10)];
    return rnd.integer(0, 1) ? d : Vec2(-d);
}

/// A random positive dyadic (1/4 .. 3): normals scaled by it keep every decision.
inline double positive_dyadic(Random& rnd) { return rnd.integer(1, 12) * 0.25; }

/// A random friction coefficient in {0, 1/4, .., 3/2}, and a kinetic one that differs from it
/// about half the time.
inline std::pair<double, double> random_mu(Random& rnd) {
    const double mu = rnd.integer(0, 6) * 0.25;
    const double mk = rnd.integer(0, 1) ? mu : rnd.integer(0, 6) * 0.25;
    return {mu, mk};
}

/// A random scene of the family with 1 .. max_contacts contacts (mostly 3 and 4), its body's
/// numbers small dyadics. `far` moves it by a dyadic offset of magnitude 2^20 .. 2^40.
inline Scene random_scene(Random& rnd, SceneFamily family, int max_contacts, bool far) {
    Scene s;
    const int n = std::min(max_contacts, rnd.integer(0, 3) == 0 ? rnd.integer(1, 2) : rnd.integer(3, 4));
    const Vec2 centre(rnd.integer(-4, 4) * 0.5, rnd.integer(-4, 4) * 0.5);
    const Vec2 line_dir = slanted_direction(rnd);
    const Vec2 shared = slanted_direction(rnd);
    static const Vec2 kCircle[] = {Vec2(5, 0), Vec2(3, 4), Vec2(4, 3), Vec2(0, 5), Vec2(-3, 4), Vec2(-4, 3), Vec2(-5, 0),
                                   Vec2(-3, -4), Vec2(-4, -3), Vec2(0, -5), Vec2(3, -4), Vec2(4, -3)};
    for (int j = 0; j < n; ++j) {
        Vec2 p, nrm;
        switch (family) {
            case SceneFamily::Concurrent: {
                const Vec2 d = slanted_direction(rnd);
                p = centre + rnd.integer(1, 3) * d;
                nrm = (rnd.integer(0, 3) ? -1.0 : 1.0) * positive_dyadic(rnd) * d;
                break;
            }
            case SceneFamily::OnACircle: {
                const Vec2 d = kCircle[rnd.integer(0, 11)];
                p = centre + d;
                nrm = -positive_dyadic(rnd) * d;
                break;
            }
            case SceneFamily::Parallel:
                p = Vec2(rnd.integer(-4, 4) * 0.25, rnd.integer(-4, 4) * 0.25);
                nrm = (rnd.integer(0, 3) ? 1.0 : -1.0) * positive_dyadic(rnd) * shared;
                break;
            case SceneFamily::Collinear:
                p = centre + rnd.integer(-3, 3) * line_dir;
                nrm = (rnd.integer(0, 2) ? 1.0 : -1.0) * positive_dyadic(rnd) * line_dir;
                break;
            case SceneFamily::SlantedIntegers:
                p = Vec2(rnd.integer(-3, 3), rnd.integer(-3, 3)) * 0.5;
                nrm = positive_dyadic(rnd) * slanted_direction(rnd);
                break;
            default:
                p = Vec2(rnd.uniform(-2, 2), rnd.uniform(-2, 2));
                nrm = Vec2(rnd.uniform(-1, 1), rnd.uniform(-1, 1));
                if (nrm.isZero()) nrm = Vec2(0, 1);
                break;
        }
        const auto [mu, mk] = random_mu(rnd);
        s.contacts.push_back(Contact::make(p, nrm, mu, mk));
    }
    s.body = Body{rnd.integer(1, 8) * 0.25, Vec2(rnd.integer(-4, 4) * 0.25, rnd.integer(-4, 4) * 0.25),
                  rnd.integer(1, 8) * 0.125, {}};
    if (far) {
        const double k = std::ldexp(1.0, rnd.integer(20, 40));
        const Vec2 offset(rnd.integer(-3, 3) * k, rnd.integer(-3, 3) * k);
        for (Contact& c : s.contacts) c.point += offset;
        s.body->com += offset;
    }
    return s;
}

/// An exact transform of scenes, of wrenches and of mode letters.
struct Transform {
    std::string name;
    // Applied to points (and the centre of mass) and to directions (normals, forces).
    Mat3 linear = Mat3::Identity();  // acts on (x, y, 1) for points, (x, y, 0) for directions
    double scale = 1.0;              // lengths times `scale` (a power of two)
    Vec2 offset = Vec2::Zero();      // then translated (points only)
    std::vector<std::size_t> order;  // new contact k is old contact order[k] (empty: the same)
    std::vector<double> normal_scale;
    bool mirror = false;             // l and r swap

    [[nodiscard]] Vec2 point(const Vec2& p) const {
        const Vec2 q = linear.topLeftCorner<2, 2>() * p * scale;
        return q + offset;
    }
    [[nodiscard]] Vec2 direction(const Vec2& d) const { return linear.topLeftCorner<2, 2>() * d; }

    [[nodiscard]] Scene apply(const Scene& s) const {
        Scene out = s;
        if (out.body) {
            out.body->com = point(s.body->com);
            out.body->inertia = s.body->inertia * scale * scale;
        }
        out.contacts.clear();
        for (std::size_t k = 0; k < s.contacts.size(); ++k) {
            const Contact& c = s.contacts[order.empty() ? k : order[k]];
            Contact d = c;
            d.point = point(c.point);
            d.normal = direction(c.normal) * (normal_scale.empty() ? 1.0 : normal_scale[k]);
            out.contacts.push_back(d);
        }
        return out;
    }
    /// The wrench (f, tau about the origin) of the transformed scene that corresponds to e, up
    /// to a positive factor: (R f, s tau' ...) with the translation's moment d x f added.
    [[nodiscard]] Vec3 wrench(const Vec3& e) const {
        const Vec2 f = direction(Vec2(e.x(), e.y()));
        const double det = linear.topLeftCorner<2, 2>().determinant();
        const double tau = det * scale * e.z() + (offset.x() * f.y() - offset.y() * f.x());
        return Vec3(f.x(), f.y(), tau);
    }
    [[nodiscard]] std::string letters(const std::string& m) const {
        std::string out(m.size(), '?');
        for (std::size_t k = 0; k < m.size(); ++k) {
            char c = m[order.empty() ? k : order[k]];
            if (mirror && c == 'l') c = 'r';
            else if (mirror && c == 'r') c = 'l';
            out[k] = c;
        }
        return out;
    }
};

/// True when every coordinate of the transformed scene, and the wrench, is exact (the
/// transform computed in doubles equals it computed in Dyadic arithmetic).
inline bool exactly_representable(const Transform& t, const Scene& s) {
    auto exact_point = [&](const Vec2& p) {
        const Mat3& m = t.linear;
        for (int i = 0; i < 2; ++i) {
            const Dyadic v = (Dyadic(m(i, 0)) * Dyadic(p.x()) + Dyadic(m(i, 1)) * Dyadic(p.y())) * Dyadic(t.scale) +
                             Dyadic(t.offset[i]);
            if (!v.fits_double() || v.to_double() != t.point(p)[i]) return false;
        }
        return true;
    };
    if (s.body && !exact_point(s.body->com)) return false;
    if (s.body && (Dyadic(s.body->inertia) * Dyadic(t.scale) * Dyadic(t.scale)).to_double() != s.body->inertia * t.scale * t.scale) {
        return false;
    }
    return std::all_of(s.contacts.begin(), s.contacts.end(), [&](const Contact& c) { return exact_point(c.point); });
}

/// A random exact transform for a scene of n contacts.
inline Transform random_transform(Random& rnd, std::size_t n) {
    Transform t;
    const int kind = rnd.integer(0, 5);
    switch (kind) {
        case 0:
            t.name = "translation";
            t.offset = Vec2(rnd.integer(-8, 8) * 0.125, rnd.integer(-8, 8) * std::ldexp(1.0, rnd.integer(-3, 30)));
            break;
        case 1:
            t.name = "quarter turn";
            t.linear << 0, -1, 0, 1, 0, 0, 0, 0, 1;
            break;
        case 2:
            t.name = "half turn";
            t.linear << -1, 0, 0, 0, -1, 0, 0, 0, 1;
            break;
        case 3:
            t.name = "mirror";
            t.linear << -1, 0, 0, 0, 1, 0, 0, 0, 1;
            t.mirror = true;
            break;
        case 4:
            t.name = "scaling";
            t.scale = std::ldexp(1.0, rnd.integer(-6, 6));
            break;
        default:
            t.name = "reordering and scaled normals";
            for (std::size_t k = 0; k < n; ++k) t.order.push_back(k);
            for (std::size_t k = n; k > 1; --k) std::swap(t.order[k - 1], t.order[static_cast<std::size_t>(rnd.integer(0, static_cast<int>(k) - 1))]);
            for (std::size_t k = 0; k < n; ++k) t.normal_scale.push_back(std::ldexp(1.0, rnd.integer(-4, 4)) * (rnd.integer(0, 1) ? 3 : 1));
            break;
    }
    return t;
}

}  // namespace momentlab::testing
