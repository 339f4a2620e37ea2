// Contact modes from the face lattice of A = {xi : N_j . xi >= 0}, refined by the signs of
// T_j . xi for the contacts that are closed (N_j . xi = 0) on each face.
//
// A face F of A, relatively open, has a set J of closed contacts; every other contact
// separates. Inside F the signs of T_j . xi (j in J) change only across the lines
// {T_j . xi = 0}: a 2-D face is cut into rays and open sectors (sorted by angle), a 1-D face
// and the 3-D interior are single cells (no contact is closed on the interior of a
// full-dimensional A). Cells with the same letters are one mode: the twists with given
// letters form a relatively open convex cone, so the closure of a mode is the sum of the
// closures of its cells. All arithmetic here is exact (Dyadic numbers; degree up to 10 in the input).
#include "momentlab/mechanics/modes.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <unordered_map>
#include <ostream>
#include <stdexcept>

#include "checks.hpp"

namespace momentlab {
namespace {

using Q3 = Exact3;

int sign(const Dyadic& q) { return to_int(q.sign()); }
int orient(const Q3& x, const Q3& y, const Q3& e) { return sign(det(x, y, e)); }

struct Cell {
    Q3 representative;             // a twist in the relative interior of the cell
    std::vector<Q3> closure;       // generators of the cell's closure (rays; lines as +-)
};

class Enumerator {
public:
    explicit Enumerator(const std::vector<Contact>& contacts) {
        for (const Contact& c : contacts) {
            normals_.push_back(c.normal_wrench());
            tangents_.push_back(c.tangent_wrench());
        }
    }

    ModeSet run(const Progress& progress) {
        ModeSet out;
        out.feasible_twists = Cone::from_halfspaces(normals_);
        const Cone& a = out.feasible_twists;
        std::vector<Q3> lineality;
        for (const ExactVector& l : a.lineality()) lineality.push_back(l.exact());
        add(std::string(normals_.size(), letter(ContactMode::Fixed)), {});  // xi = 0: every contact fixed
        const std::vector<Face> faces = a.faces();
        for (std::size_t f = 0; f < faces.size(); ++f) {
            if (progress) progress("faces of the cone of motions", f, faces.size());
            const Face& face = faces[f];
            if (face.dimension == 0) continue;
            std::vector<Q3> rays;
            for (int i : face.rays) rays.push_back(a.rays()[static_cast<std::size_t>(i)].exact());
            // Closed on the face: N_j . g = 0 for every generator g of it (filtered predicates:
            // this and the letters are the Theta(faces x n) and Theta(modes x n) parts).
            std::vector<bool> closed(normals_.size());
            for (std::size_t j = 0; j < normals_.size(); ++j) {
                bool all = true;
                for (int i : face.rays) {
                    all = all && dot_sign(normals_[j], a.rays()[static_cast<std::size_t>(i)]) == Sign::Zero;
                }
                for (const ExactVector& l : a.lineality()) all = all && dot_sign(normals_[j], l) == Sign::Zero;
                closed[j] = all;
            }
            for (const Cell& cell : cells(face.dimension, rays, lineality, closed)) {
                add(letters(cell.representative, closed), cell.closure);
            }
        }
        out.modes.resize(order_.size());
        while (!order_.empty()) {  // each key moved out, not copied: the letters are Theta(M n)
            auto node = order_.extract(order_.begin());
            const std::size_t index = node.mapped();
            std::vector<ExactVector> gens;
            for (const Q3& g : closures_[index]) gens.push_back(ExactVector::from_exact(g));
            closures_[index] = {};
            out.modes[index] = Mode{std::move(node.key()), Cone::from_generators(gens)};
        }
        return out;
    }

private:
    std::string letters(const Q3& representative, const std::vector<bool>& closed) const {
        const ExactVector xi = ExactVector::from_exact(representative);
        std::string s(normals_.size(), letter(ContactMode::Separating));
        for (std::size_t j = 0; j < normals_.size(); ++j) {
            if (!closed[j]) continue;
            const Sign v = dot_sign(tangents_[j], xi);
            s[j] = letter(v == Sign::Positive ? ContactMode::SlidingRight
                                              : (v == Sign::Negative ? ContactMode::SlidingLeft : ContactMode::Fixed));
        }
        return s;
    }

    void add(const std::string& letters, const std::vector<Q3>& closure) {
        auto [it, inserted] = order_.emplace(letters, closures_.size());
        if (inserted) closures_.emplace_back();
        auto& gens = closures_[it->second];
        gens.insert(gens.end(), closure.begin(), closure.end());
    }

    // The cells of the relatively open face spanned by `rays` and `lineality`.
    std::vector<Cell> cells(int dimension, const std::vector<Q3>& rays, const std::vector<Q3>& lineality,
                            const std::vector<bool>& closed) const {
        std::vector<Cell> out;
        auto with_lines = [&](std::vector<Q3> gens) {
            for (const Q3& l : lineality) {
                gens.push_back(l);
                gens.push_back(-l);
            }
            return gens;
        };
        if (dimension == 3) {
            // The interior of a full-dimensional A: no contact is closed there. The sum of the
            // rays is interior (pointed cone, wedge x line, half-space); for R^3 any vector.
            assert(std::none_of(closed.begin(), closed.end(), [](bool c) { return c; }));
            Q3 inside = rays.empty() ? lineality.front() : rays.front();
            for (std::size_t i = 1; i < rays.size(); ++i) inside = inside + rays[i];
            return {{inside, with_lines(rays)}};
        }
        if (dimension == 1) {
            if (!rays.empty()) return {{rays.front(), {rays.front()}}};
            return {{lineality.front(), {lineality.front()}}, {-lineality.front(), {-lineality.front()}}};
        }
        // Dimension 2: a wedge (two rays), a half-plane (a line and a ray) or a plane.
        Q3 start, finish, e;
        enum class Shape { Wedge, HalfPlane, Plane } shape;
        if (lineality.empty()) {
            shape = Shape::Wedge;
            start = rays[0];
            finish = rays[1];
            e = cross(start, finish);
            if (orient(start, finish, e) < 0) std::swap(start, finish);
            e = cross(start, finish);
        } else if (lineality.size() == 1) {
            shape = Shape::HalfPlane;
            start = lineality[0];
            finish = -start;
            e = cross(start, rays[0]);
        } else {
            shape = Shape::Plane;
            start = lineality[0];
            e = cross(lineality[0], lineality[1]);
        }
        auto inside = [&](const Q3& x) {
            if (shape == Shape::Wedge) return orient(start, x, e) > 0 && orient(x, finish, e) > 0;
            if (shape == Shape::HalfPlane) return orient(start, x, e) > 0;
            return true;
        };
        std::vector<Q3> critical;
        for (std::size_t j = 0; j < tangents_.size(); ++j) {
            if (!closed[j]) continue;
            const Q3 u = cross(e, tangents_[j].exact());
            if (is_zero(u)) continue;  // T_j vanishes on the whole face
            for (const Q3& x : {u, -u}) {
                if (inside(x)) critical.push_back(x);
            }
        }
        // Angular order counter-clockwise about e, from `start` (full turn for the plane).
        auto half = [&](const Q3& x) {
            const int o = orient(start, x, e);
            if (o > 0) return 1;
            if (o < 0) return 3;
            return sign(dot(start, x)) > 0 ? 0 : 2;
        };
        std::sort(critical.begin(), critical.end(), [&](const Q3& x, const Q3& y) {
            const int hx = half(x), hy = half(y);
            if (hx != hy) return hx < hy;
            return orient(x, y, e) > 0;
        });
        critical.erase(std::unique(critical.begin(), critical.end(),
                                   [&](const Q3& x, const Q3& y) {
                                       return half(x) == half(y) && orient(x, y, e) == 0;
                                   }),
                       critical.end());
        for (const Q3& c : critical) out.push_back({c, {c}});
        auto sector = [&](const Q3& a, const Q3& b) -> Cell {
            if (orient(a, b, e) > 0) return {a + b, {a, b}};
            const Q3 perpendicular = cross(e, a);  // a turned by a quarter counter-clockwise
            return {perpendicular, {a, -a, perpendicular}};
        };
        if (shape == Shape::Plane) {
            if (critical.empty()) return {{start, with_lines({})}};
            for (std::size_t i = 0; i < critical.size(); ++i) {
                out.push_back(sector(critical[i], critical[(i + 1) % critical.size()]));
            }
            return out;
        }
        std::vector<Q3> sequence = {start};
        sequence.insert(sequence.end(), critical.begin(), critical.end());
        sequence.push_back(finish);
        for (std::size_t i = 0; i + 1 < sequence.size(); ++i) {
            if (shape == Shape::HalfPlane && critical.empty()) {
                out.push_back({rays[0], {start, finish, rays[0]}});
            } else {
                out.push_back(sector(sequence[i], sequence[i + 1]));
            }
        }
        return out;
    }

    std::vector<ExactVector> normals_, tangents_;
    std::unordered_map<std::string, std::size_t> order_;
    std::vector<std::vector<Q3>> closures_;
};

}  // namespace

void detail::check_contacts(const std::vector<Contact>& contacts) {
    for (const Contact& c : contacts) {
        if (!c.point.allFinite() || !c.normal.allFinite() || (c.normal.x() == 0.0 && c.normal.y() == 0.0) ||
            !(c.mu >= 0.0) || !(c.mu_kinetic >= 0.0) || !std::isfinite(c.mu) || !std::isfinite(c.mu_kinetic)) {
            throw std::invalid_argument("enumerate_modes: every contact needs a finite point, a finite non-zero normal and finite mu, mu_kinetic >= 0 (Contact::make)");
        }
    }
}

ModeSet enumerate_modes(const std::vector<Contact>& contacts, const Progress& progress) {
    detail::check_contacts(contacts);
    return Enumerator(contacts).run(progress);
}

ContactMode contact_mode(char c) {
    switch (c) {
        case 's': return ContactMode::Separating;
        case 'f': return ContactMode::Fixed;
        case 'r': return ContactMode::SlidingRight;
        case 'l': return ContactMode::SlidingLeft;
        default: throw std::invalid_argument(std::string("contact_mode: expected a letter s, f, r or l, got '") + c + "'");
    }
}

const char* describe(ContactMode m) {
    switch (m) {
        case ContactMode::Separating: return "separates";
        case ContactMode::Fixed: return "fixed";
        case ContactMode::SlidingRight: return "slides along +t";
        case ContactMode::SlidingLeft: return "slides along -t";
    }
    return "?";
}

std::ostream& operator<<(std::ostream& out, ContactMode m) { return out << letter(m); }

Labels rotation_centres(const Mode& mode) { return Labels(mode.twists.dual()); }

}  // namespace momentlab
