// The tilting-table test (docs/assemblies.md, "Tilt"): the gravity vectors g for which an
// equilibrium exists are {g : -Gamma g in cone(A)}, the preimage of the contact forces' cone
// under the linear map g -> gravity wrenches: a closed convex cone of the plane. It is found
// from four charts, the lines u . g = 1 for u = (0, -1), (1, 0), (0, 1), (-1, 0): in each, the
// gravity vectors u + s u_perp that stand form an interval of s whose ends are exact optima of
// linear programs. Their ends are the cone's boundary rays, from which its kind follows.
#include <stdexcept>

#include "assembly_programs.hpp"
#include "momentlab/assembly/stand.hpp"

namespace momentlab {

using namespace assembly_detail;

namespace {

using Direction = std::array<assembly_detail::Rational, 2>;

assembly_detail::Rational cross(const Direction& a, const Direction& b) { return a[0] * b[1] - a[1] * b[0]; }
assembly_detail::Rational dot(const Direction& a, const Direction& b) { return a[0] * b[0] + a[1] * b[1]; }
bool same_ray(const Direction& a, const Direction& b) { return cross(a, b) == 0 && dot(a, b) > 0; }
Direction opposite(const Direction& a) { return {assembly_detail::Rational(-a[0]), assembly_detail::Rational(-a[1])}; }

ExactDirection exact_direction(const Direction& d) {
    const assembly_detail::Rational scale = max(abs(d[0]), abs(d[1]));
    ExactDirection out;
    for (int i = 0; i < 2; ++i) {
        const assembly_detail::Rational v = d[static_cast<std::size_t>(i)] / scale;
        out.exact[static_cast<std::size_t>(i)] = exact_text(v);
        out.rounded[i] = approximate(v);
        out.is_double[static_cast<std::size_t>(i)] = is_double(v);
    }
    return out;
}

class TiltSearch {
public:
    explicit TiltSearch(const Assembly& assembly) : assembly_(assembly), d_(assembly_data<Interval>(assembly)) {}

    TiltCone run() {
        const int charts[4][2] = {{0, -1}, {1, 0}, {0, 1}, {-1, 0}};
        std::vector<Direction> ends;
        int feasible = 0;
        for (const auto& u : charts) {
            const Program<Interval> p = tilt_program(d_, u[0], u[1]);
            const auto exact = [&] { return tilt_program(exact_data(), u[0], u[1]); };
            Program<Interval> margin = p;  // feasibility first, with a margin on the forces
            for (std::size_t j = 0; j + 1 < margin.strict.size(); ++j) margin.strict[j] = true;
            const FeasibilityAnswer f = decide(margin, [&] {
                Program<assembly_detail::Rational> e = exact();
                for (std::size_t j = 0; j + 1 < e.strict.size(); ++j) e.strict[j] = true;
                return e;
            });
            if (f.status == Feasibility::Infeasible) continue;
            ++feasible;
            const auto s = static_cast<std::uint32_t>(p.columns.size() - 1);
            for (int sign : {1, -1}) {
                const Optimum o = maximize(p, exact, {{s, sign}});
                if (o.status != Optimum::Status::Optimal) continue;
                const assembly_detail::Rational end = sign > 0 ? o.value : assembly_detail::Rational(-o.value);
                // u + end * u_perp, u_perp = (-u.y, u.x)
                const Direction d{assembly_detail::Rational(u[0]) - end * u[1], assembly_detail::Rational(u[1]) + end * u[0]};
                bool known = false;
                for (const Direction& e : ends) known = known || same_ray(e, d);
                if (!known) ends.push_back(d);
            }
        }
        TiltCone cone;
        if (feasible == 0) return cone;
        if (ends.empty()) {
            cone.kind = TiltCone::Kind::Plane;
            return cone;
        }
        if (ends.size() == 1) {
            cone.kind = TiltCone::Kind::Ray;
            cone.directions = {exact_direction(ends[0])};
            return cone;
        }
        if (ends.size() != 2) throw std::logic_error("tilt_cone: a convex cone of the plane has at most two boundary rays");
        const Direction& a = ends[0];
        const Direction& b = ends[1];
        if (cross(a, b) != 0) {
            cone.kind = TiltCone::Kind::Wedge;
            cone.directions = cross(a, b) > 0 ? std::vector{exact_direction(a), exact_direction(b)}
                                              : std::vector{exact_direction(b), exact_direction(a)};
            return cone;
        }
        // a and -a: a line, or the half-plane on the side of a perpendicular that stands.
        const Direction left{assembly_detail::Rational(-a[1]), a[0]};
        if (stands(left)) {
            cone.kind = TiltCone::Kind::HalfPlane;
            cone.directions = {exact_direction(a), exact_direction(opposite(a))};
        } else if (stands(opposite(left))) {
            cone.kind = TiltCone::Kind::HalfPlane;
            cone.directions = {exact_direction(opposite(a)), exact_direction(a)};
        } else {
            cone.kind = TiltCone::Kind::Line;
            cone.directions = {exact_direction(a), exact_direction(opposite(a))};
        }
        return cone;
    }

private:
    const AssemblyData<assembly_detail::Rational>& exact_data() {
        if (!exact_) exact_ = assembly_data<assembly_detail::Rational>(assembly_);
        return *exact_;
    }

    bool stands(const Direction& g) {
        const FeasibilityAnswer f = decide(equilibrium_program(d_, enclose(g[0]), enclose(g[1])),
                                           [&] { return equilibrium_program(exact_data(), g[0], g[1]); });
        return f.status != Feasibility::Infeasible;
    }

    const Assembly& assembly_;
    AssemblyData<Interval> d_;
    std::optional<AssemblyData<assembly_detail::Rational>> exact_;
};

}  // namespace

const char* to_string(TiltCone::Kind kind) {
    switch (kind) {
        case TiltCone::Kind::Empty: return "empty";
        case TiltCone::Kind::Ray: return "ray";
        case TiltCone::Kind::Wedge: return "wedge";
        case TiltCone::Kind::HalfPlane: return "halfplane";
        case TiltCone::Kind::Line: return "line";
        case TiltCone::Kind::Plane: return "plane";
    }
    return "empty";
}

TiltCone tilt_cone(const Assembly& assembly) {
    check_assembly(assembly);
    return TiltSearch(assembly).run();
}

}  // namespace momentlab
