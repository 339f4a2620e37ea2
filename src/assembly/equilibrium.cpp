// Equilibrium of an assembly (docs/assemblies.md, "Can it stand?"): one linear program, the
// contact forces' friction-cone edges as columns, each body's three equations as rows; a point
// is an equilibrium, a Farkas vector a collapse mechanism.
#include <algorithm>
#include <cmath>

#include "assembly_programs.hpp"
#include "momentlab/assembly/stand.hpp"

namespace momentlab {

using namespace assembly_detail;

namespace {

// The edge direction of a contact's cone, rounded (for the forces printed).
Vec2 edge_direction(const Contact& c, Index edge) {
    if (c.mu == 0.0) return c.normal;
    const auto d = friction_direction(c.normal.x(), c.normal.y(), edge == 0 ? c.mu : -c.mu);
    return Vec2(d[0], d[1]);
}

BodyMotion body_motion(const Vec3& twist) {
    BodyMotion m;
    m.twist = twist;
    if (twist.z() != 0.0) m.rotation_centre = Vec2(-twist.y() / twist.z(), twist.x() / twist.z());
    return m;
}

}  // namespace

Equilibrium equilibrium(const Assembly& assembly, const Rational2& gravity) {
    check_assembly(assembly);
    if (!to_double(gravity).allFinite()) throw std::invalid_argument("gravity: expected finite numbers");
    const AssemblyData<Interval> d = assembly_data<Interval>(assembly);
    std::vector<ForceColumn> columns;
    const Program<Interval> p = equilibrium_program(d, number<Interval>(gravity[0]), number<Interval>(gravity[1]), &columns);
    const FeasibilityAnswer answer = decide(p, [&] {
        const AssemblyData<assembly_detail::Rational> e = assembly_data<assembly_detail::Rational>(assembly);
        return equilibrium_program(e, exact_value(gravity[0]), exact_value(gravity[1]));
    });
    Equilibrium out;
    out.can_stand = answer.status != Feasibility::Infeasible;
    if (out.can_stand) {
        out.forces.assign(assembly.contacts.size(), Vec2::Zero());
        for (std::size_t k = 0; k < columns.size(); ++k) {
            const ForceColumn& f = columns[k];
            out.forces[f.contact] += answer.point[k] * edge_direction(assembly.contacts[f.contact].contact, f.edge);
        }
        return out;
    }
    // y . A_j <= 0 for every edge and y . (-G) > 0: the twist -y is allowed at every contact and
    // gravity does positive work along it. Scaled so that its largest coordinate is 1.
    double largest = 0.0;
    for (double v : answer.farkas) largest = std::max(largest, std::abs(v));
    for (std::size_t k = 0; k < assembly.bodies.size(); ++k) {
        Vec3 twist(-answer.farkas[3 * k], -answer.farkas[3 * k + 1], -answer.farkas[3 * k + 2]);
        if (largest > 0.0) twist /= largest;
        out.mechanism.push_back(body_motion(twist));
    }
    return out;
}

}  // namespace momentlab
