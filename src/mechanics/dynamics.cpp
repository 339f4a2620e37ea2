#include "momentlab/mechanics/dynamics.hpp"

#include <stdexcept>

#include "momentlab/geometry/force_sets.hpp"

namespace momentlab {

Mat3 inertia_at_origin(const Body& body) {
    const double m = body.mass, cx = body.com.x(), cy = body.com.y();
    Mat3 mat;
    mat << m, 0.0, -m * cy, 0.0, m, m * cx, -m * cy, m * cx, body.inertia + m * (cx * cx + cy * cy);
    return mat;
}

std::vector<ModeForces> analyze(const Scene& scene) {
    if (!scene.body) throw std::invalid_argument("analyze: the scene needs a body (mass, com, inertia)");
    const Mat3 m = inertia_at_origin(*scene.body);
    const ModeSet modes = enumerate_modes(scene.contacts);
    std::vector<ModeForces> out;
    out.reserve(modes.modes.size());
    for (const Mode& mode : modes.modes) {
        std::vector<Vec3> contact_generators;
        for (std::size_t j = 0; j < scene.contacts.size(); ++j) {
            const Contact& c = scene.contacts[j];
            switch (mode.letters[j]) {
                case 'f': {  // anywhere in the friction cone (static mu)
                    const auto edges = friction_cone_edges(c.point, c.normal, c.mu);
                    contact_generators.insert(contact_generators.end(), edges.begin(), edges.end());
                    break;
                }
                case 'r':  // friction opposes sliding along +t: n - mu_k t
                    contact_generators.push_back(friction_cone_edges(c.point, c.normal, c.mu_kinetic)[1]);
                    break;
                case 'l':  // n + mu_k t
                    contact_generators.push_back(friction_cone_edges(c.point, c.normal, c.mu_kinetic)[0]);
                    break;
                default:
                    break;
            }
        }
        ModeForces f{mode, mode.twists.linear_image(m), Cone::from_generators(contact_generators), Cone()};
        f.applied = sum(f.total, f.contact.negated());
        out.push_back(std::move(f));
    }
    return out;
}

const char* to_string(Verdict v) {
    switch (v) {
        case Verdict::Unique: return "unique";
        case Verdict::Ambiguous: return "ambiguous";
        default: return "inconsistent";
    }
}

QueryResult query(const std::vector<ModeForces>& analysis, const Vec3& e) {
    if (!e.allFinite()) throw std::invalid_argument("query: the wrench must be finite");
    QueryResult r;
    for (std::size_t i = 0; i < analysis.size(); ++i) {
        if (analysis[i].applied.has(e)) r.modes.push_back(i);
    }
    r.verdict = r.modes.empty() ? Verdict::Inconsistent : (r.modes.size() == 1 ? Verdict::Unique : Verdict::Ambiguous);
    return r;
}

}  // namespace momentlab
