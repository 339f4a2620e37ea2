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
#include <functional>
#include <initializer_list>
#include <span>
#include <ostream>
#include <stdexcept>

#include "checks.hpp"
#include "momentlab/geometry/angular_order.hpp"
#include "mode_walk.hpp"

namespace momentlab {
namespace {

using Q3 = Exact3;
using Visit = std::function<void(const detail::WalkCell&)>;

int sign(const Dyadic& q) { return to_int(q.sign()); }
int orient(const Q3& x, const Q3& y, const Q3& e) { return sign(det(x, y, e)); }

char letter_of(Sign v) {
    return letter(v == Sign::Positive ? ContactMode::SlidingRight
                                      : (v == Sign::Negative ? ContactMode::SlidingLeft : ContactMode::Fixed));
}

// The walk over one face: its cells, their mode indices and their letters. Each cell's closure
// is written into `closure` (the caller's buffer, reused from cell to cell and face to face:
// the visit reads it, no cell allocates).
class FaceWalk {
public:
    FaceWalk(std::size_t face, std::span<const int> closed, const std::vector<ExactVector>& tangents, std::size_t contacts,
             std::size_t& next, const Visit& visit, std::vector<Q3>& closure)
        : face_(face), closed_(closed), tangents_(tangents), contacts_(contacts), next_(next), visit_(visit),
          letters_(closed.size()), closure_(closure) {}

    // The cells of the relatively open face spanned by `rays` and `lineality`.
    // `ray` is the face's ray as A stores it, for a 1-D face with a ray (its letters need no
    // new exact vector).
    // `normal`, for a wedge of a full-dimensional A, is A's facet on it (else null).
    void run(int dimension, const std::vector<Q3>& rays, const std::vector<Q3>& lineality, const ExactVector* ray,
             const ExactVector* start, const ExactVector* finish, const ExactVector* normal) {
        start_vector_ = start;
        finish_vector_ = finish;
        normal_vector_ = normal;
        if (dimension == 3) {
            // The interior of a full-dimensional A: no contact is closed there, so every letter
            // is 's' and the cell's closure is A itself. With contacts, no closure is given (the
            // callers take A for it: 10^5 rays on the tangent family, which `rays` then leaves
            // out); with none, A is R^3 and the cell is the all-f mode, xi = 0 included: its
            // closure is A's lines, +- each. The sum of the rays is interior (pointed cone,
            // wedge x line, half-space); for R^3 any vector.
            assert(closed_.empty());
            closure_.clear();
            if (contacts_ > 0) {
                emit(index_of(false), true);
                return;
            }
            Q3 inside = rays.empty() ? lineality.front() : rays.front();
            for (std::size_t i = 1; i < rays.size(); ++i) inside = inside + rays[i];
            closure_.assign(rays.begin(), rays.end());
            add_lines(lineality);
            single(inside);
            return;
        }
        if (dimension == 1) {
            if (!rays.empty()) {  // its letters at the ray as A stores it
                assert(ray);
                const std::size_t index = index_of(direct(*ray));
                set_closure({&rays.front()});
                emit(index, true);
            } else {
                const Q3& line = lineality.front();
                const Q3 opposite = -line;
                set_closure({&line});
                single(line);
                set_closure({&opposite});
                single(opposite);
            }
            return;
        }
        planar(rays, lineality);
    }

private:
    // Letters from the signs of T_j . xi (all of them; O(closed)). Returns whether all are 'f'.
    bool direct(const Q3& representative) { return direct(ExactVector::from_exact(representative)); }
    bool direct(const ExactVector& xi) {
        bool all_fixed = true;
        for (std::size_t t = 0; t < closed_.size(); ++t) {
            letters_[t] = letter_of(dot_sign(tangents_[static_cast<std::size_t>(closed_[t])], xi));
            all_fixed = all_fixed && letters_[t] == 'f';
        }
        return all_fixed;
    }

    // A cell whose letters are all 'f' joins mode 0 (xi = 0, every contact fixed); every other
    // cell is a mode of its own (the letters tell the face, and the cells of a face apart).
    std::size_t index_of(bool all_fixed) { return all_fixed && closed_.size() == contacts_ ? 0 : next_++; }

    // The closure: the given generators (copied into the buffer's own numbers).
    void set_closure(std::initializer_list<const Q3*> generators) {
        closure_.resize(generators.size());
        std::size_t i = 0;
        for (const Q3* g : generators) closure_[i++] = *g;
    }
    void add_lines(const std::vector<Q3>& lineality) {
        for (const Q3& l : lineality) {
            closure_.push_back(l);
            closure_.push_back(-l);
        }
    }

    // A cell of one representative, its closure already set.
    void single(const Q3& representative) {
        const std::size_t index = index_of(direct(representative));
        emit(index, true, {}, &representative);
    }

    // A point inside the cell whose closure set_sector or a single ray gives.
    static Q3 rep_of(const std::vector<Q3>& closure) {
        if (closure.size() == 1) return closure[0];
        return closure.size() == 2 ? closure[0] + closure[1] : closure[2];
    }

    void emit(std::size_t index, bool first, std::span<const int> changed = {}, const Q3* representative = nullptr) {
#ifndef NDEBUG
        // The letters kept up to date along the walk are the signs at the cell's representative
        // (none to check for the interior of A, which has no letter but 's').
        if (representative || !closure_.empty()) {
            const std::vector<char> walked = letters_;
            direct(representative ? *representative : rep_of(closure_));
            assert(walked == letters_);
        }
#else
        (void)representative;
#endif
        detail::WalkCell cell;
        cell.index = index;
        cell.face = face_;
        cell.closure = &closure_;
        cell.closed = closed_;
        cell.letters = letters_;
        cell.changed = changed;
        cell.first = first;
        visit_(cell);
    }

    void planar(const std::vector<Q3>& rays, const std::vector<Q3>& lineality) {
        // Dimension 2: a wedge (two rays), a half-plane (a line and a ray) or a plane.
        const Q3* start = nullptr;
        const Q3* finish = nullptr;
        Q3 opposite, e;  // a half-plane's finish, -start
        enum class Shape { Wedge, HalfPlane, Plane } shape;
        if (lineality.empty()) {
            shape = Shape::Wedge;
            start = &rays[0];
            finish = &rays[1];
            // A positive multiple of start x finish (det(start, finish, e) > 0: counter-clockwise
            // about e): the facet of A on the wedge, signed, where A gives it. A's rays are
            // products of its facets, so start x finish has twice their degree and the crossings
            // u = e x T_j below twice theirs again; the facet keeps both small.
            if (normal_vector_ != nullptr) {
                const Sign turn = det_sign(*start_vector_, *finish_vector_, *normal_vector_);
                assert(turn != Sign::Zero);
                e = turn == Sign::Positive ? normal_vector_->exact() : -normal_vector_->exact();
            } else {
                e = cross(*start, *finish);
            }
        } else if (lineality.size() == 1) {
            shape = Shape::HalfPlane;
            start = &lineality[0];
            opposite = -*start;
            finish = &opposite;
            e = cross(*start, rays[0]);
        } else {
            shape = Shape::Plane;
            start = &lineality[0];
            e = cross(lineality[0], lineality[1]);
        }
        // Where T_j . xi = 0 meets the face: u = e x T_j and -u. Since e is orthogonal to
        // `start` (and to `finish`), det(start, u, e) = |e|^2 (T_j . start) and det(u, finish, e)
        // = -|e|^2 (T_j . finish): whether u lies inside the face, and on which side of start,
        // are filtered signs of T_j at the face's own generators.
        const ExactVector& start_v = *start_vector_;
        struct Critical {
            Q3 x;
            int position;
            int half;  // about e from `start`: 0 along it, 1 within pi counter-clockwise, 2 opposite, 3 the rest
        };
        std::vector<Critical> critical;
        std::size_t vanishing = 0;  // contacts whose T_j vanishes on the whole face: always 'f'
        // The signs just after `start` (a wedge's or half-plane's first sector): T_j at start,
        // or where T_j . start = 0, T_j at the other generator.
        std::vector<Sign> signs(closed_.size(), Sign::Zero);
        for (std::size_t t = 0; t < closed_.size(); ++t) {
            const ExactVector& tangent = tangents_[static_cast<std::size_t>(closed_[t])];
            const Sign at_start = dot_sign(tangent, start_v);
            const int position = static_cast<int>(t);
            if (shape != Shape::Plane) {
                // T_j vanishes on the face (u = 0) iff it does on both vectors that span it; u
                // itself, a product in Dyadic numbers, is made only for a line that crosses. (A
                // half-plane needs T_j at its ray only where T_j . start = 0.)
                const Sign at_finish = shape == Shape::Wedge || at_start == Sign::Zero
                                           ? dot_sign(tangent, *finish_vector_)
                                           : Sign::Zero;
                if (at_start == Sign::Zero && at_finish == Sign::Zero) {
                    ++vanishing;
                    continue;
                }
                signs[t] = at_start != Sign::Zero ? at_start : at_finish;
                const bool crosses = at_start != Sign::Zero && (shape == Shape::HalfPlane || at_finish == -at_start);
                if (crosses) {
                    Q3 u = cross(e, tangent.exact());
                    if (at_start != Sign::Positive) u = -u;
                    critical.push_back({std::move(u), position, 1});
                }
                continue;
            }
            const Q3 u = cross(e, tangent.exact());
            if (is_zero(u)) {
                ++vanishing;
                continue;
            }
            const int half_u = angular_half(at_start, [&] { return sign(dot(*start, u)) > 0; });
            critical.push_back({u, position, half_u});
            critical.push_back({-u, position, (half_u + 2) % 4});
        }
        // Angular order counter-clockwise about e, from `start` (full turn for the plane).
        const auto compare = [&](const Critical& a, const Critical& b) {
            return angular_compare(a.half, b.half, [&] { return det(a.x, b.x, e).sign(); });
        };
        std::sort(critical.begin(), critical.end(),
                  [&](const Critical& a, const Critical& b) { return compare(a, b) == Sign::Negative; });
        // Groups of one direction; the first of each is its ray.
        std::vector<std::size_t> group = {};
        std::vector<int> members;  // positions, group by group
        std::vector<std::size_t> member_start;
        for (std::size_t i = 0; i < critical.size(); ++i) {
            const bool same = !group.empty() && compare(critical[group.back()], critical[i]) == Sign::Zero;
            if (!same) {
                group.push_back(i);
                member_start.push_back(members.size());
            }
            members.push_back(critical[i].position);
        }
        member_start.push_back(members.size());
        const std::size_t r_count = group.size();
        const auto ray = [&](std::size_t r) -> const Q3& { return critical[group[r % r_count]].x; };
        const auto group_members = [&](std::size_t r) {
            return std::span<const int>(members.data() + member_start[r], member_start[r + 1] - member_start[r]);
        };
        // A sector's closure; its representative is the sum of the two, or the third (rep_of).
        // Only a plane's sectors can reach pi (two opposite rays).
        const auto set_sector = [&](const Q3& a, const Q3& b) {
            if (shape != Shape::Plane || orient(a, b, e) > 0) {
                set_closure({&a, &b});
                return;
            }
            const Q3 quarter = cross(e, a);  // a turned by a quarter counter-clockwise
            const Q3 back = -a;
            set_closure({&a, &back, &quarter});
        };
        if (r_count == 0) {
            if (shape == Shape::Plane) {
                closure_.clear();
                add_lines(lineality);
                single(*start);
            } else if (shape == Shape::HalfPlane) {
                set_closure({start, finish, &rays[0]});
                single(rays[0]);
            } else {
                set_sector(*start, *finish);
                const Q3 representative = rep_of(closure_);
                single(representative);
            }
            return;
        }
        // Mode indices in enumerate_modes' order: the rays, then the sectors. A ray is all 'f'
        // when every contact is closed here and each T_j vanishes on the face or changes sign there.
        const bool all_closed = closed_.size() == contacts_;
        std::vector<std::size_t> ray_index(r_count), sector_index(shape == Shape::Plane ? r_count : r_count + 1);
        for (std::size_t r = 0; r < r_count; ++r) {
            ray_index[r] = all_closed && vanishing + group_members(r).size() == closed_.size() ? 0 : next_++;
        }
        for (std::size_t& i : sector_index) i = next_++;
        // The sectors counter-clockwise: sector i lies after ray i - 1 (plane: after ray i).
        std::vector<const Q3*> sequence;
        if (shape != Shape::Plane) {
            sequence.push_back(start);
            for (std::size_t r = 0; r < r_count; ++r) sequence.push_back(&ray(r));
            sequence.push_back(finish);
        }
        const auto set_sector_at = [&](std::size_t i) {
            if (shape == Shape::Plane) {
                set_sector(ray(i), ray(i + 1));
            } else {
                set_sector(*sequence[i], *sequence[i + 1]);
            }
        };
        // Signs of the sector before the first ray visited: the last sector of the plane's turn
        // (at its representative), the first sector of a wedge or half-plane (found above).
        if (shape == Shape::Plane) {
            set_sector_at(r_count - 1);
            const ExactVector xi = ExactVector::from_exact(rep_of(closure_));
            for (std::size_t t = 0; t < closed_.size(); ++t) signs[t] = dot_sign(tangents_[static_cast<std::size_t>(closed_[t])], xi);
        }
        for (std::size_t t = 0; t < closed_.size(); ++t) letters_[t] = letter_of(signs[t]);
        if (shape != Shape::Plane) {
            set_sector_at(0);
            emit(sector_index[0], true);
        }
        bool first = shape == Shape::Plane;
        for (std::size_t r = 0; r < r_count; ++r) {
            const std::span<const int> changed = group_members(r);
            for (int t : changed) letters_[static_cast<std::size_t>(t)] = 'f';
            set_closure({&ray(r)});
            emit(ray_index[r], first, changed);
            first = false;
            for (int t : changed) {
                Sign& s = signs[static_cast<std::size_t>(t)];
                s = -s;  // the line T_j . xi = 0 crossed
                letters_[static_cast<std::size_t>(t)] = letter_of(s);
            }
            const std::size_t i = shape == Shape::Plane ? r : r + 1;
            set_sector_at(i);
            emit(sector_index[i], false, changed);
        }
    }

    std::size_t face_;
    const ExactVector* start_vector_ = nullptr;   // a 2-D face: its first ray, or its line
    const ExactVector* finish_vector_ = nullptr;  // a wedge: its second ray; a half-plane: its ray
    const ExactVector* normal_vector_ = nullptr;  // a wedge: A's facet on it (or none)
    std::span<const int> closed_;
    const std::vector<ExactVector>& tangents_;
    std::size_t contacts_;
    std::size_t& next_;
    const Visit& visit_;
    std::vector<char> letters_;
    std::vector<Q3>& closure_;
};

}  // namespace

namespace detail {

ModeWalk::ModeWalk(const std::vector<Contact>& contacts, Closed how) {
    normals_.reserve(contacts.size());
    tangents_.reserve(contacts.size());
    for (const Contact& c : contacts) {
        normals_.push_back(c.normal_wrench());
        tangents_.push_back(c.tangent_wrench());
    }
    a_ = Cone::from_halfspaces(normals_);
    for (const ExactVector& l : a_.lineality()) lineality_.push_back(l.exact());
    faces_ = a_.faces();
    closed_ = closed_sets(faces_, how);
}

void ModeWalk::run_faces(std::size_t begin, std::size_t end, const Progress& progress, std::vector<std::size_t>& counts,
                         const Visit& visit) const {
    std::vector<Q3> closure;  // every cell's, in turn
    for (std::size_t i = begin; i < end; ++i) {
        if (progress) progress("faces of the cone of motions", i - begin, end - begin);
        const Face& face = faces_[i];
        std::size_t next = 1;
        if (face.dimension > 0) {
            // (The interior of A needs its rays only when there is no contact: FaceWalk::run.)
            std::vector<Q3> rays;
            if (face.dimension < 3 || normals_.empty()) {
                for (int r : face.rays) rays.push_back(a_.rays()[static_cast<std::size_t>(r)].exact());
            }
            // A's own vectors for the face's generators: filtered signs against them.
            const auto a_ray = [&](std::size_t k) { return &a_.rays()[static_cast<std::size_t>(face.rays[k])]; };
            const ExactVector* ray = face.dimension == 1 && face.rays.size() == 1 ? a_ray(0) : nullptr;
            const ExactVector* start = nullptr;
            const ExactVector* finish = nullptr;
            const ExactVector* normal = nullptr;
            if (face.dimension == 2) {
                start = a_.lineality().empty() ? a_ray(0) : &a_.lineality().front();
                finish = a_.lineality().empty() ? a_ray(1) : (a_.lineality().size() == 1 ? a_ray(0) : nullptr);
                if (a_.lineality().empty() && face.facets.size() == 1) {
                    normal = &a_.facets()[static_cast<std::size_t>(face.facets.front())];
                }
            }
            FaceWalk(i, closed_[i], tangents_, normals_.size(), next, visit, closure)
                .run(face.dimension, rays, lineality_, ray, start, finish, normal);
        }
        counts[i] = next - 1;
    }
}

std::size_t ModeWalk::run(const Progress& progress, const Visit& visit) const {
    std::vector<std::size_t> counts(faces_.size());
    std::size_t base = 0;  // the modes of the faces before; mode 0 is xi = 0, every contact fixed
    for (std::size_t i = 0; i < faces_.size(); ++i) {
        run_faces(i, i + 1, nullptr, counts, [&](const WalkCell& cell) {
            WalkCell global = cell;
            if (global.index != 0) global.index += base;
            visit(global);
        });
        if (progress) progress("faces of the cone of motions", i, faces_.size());
        base += counts[i];
    }
    return base + 1;
}

}  // namespace detail

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
    const detail::ModeWalk walk(contacts);
    const std::size_t n = contacts.size();
    std::vector<std::string> letters(1, std::string(n, letter(ContactMode::Fixed)));
    std::vector<std::vector<Q3>> closures(1);
    // The interior of a full-dimensional A, where no contact is closed, is a mode whose closure
    // is A itself: not built again from A's rays (10^5 of them on the tangent family).
    std::size_t interior = 0;
    walk.run(progress, [&](const detail::WalkCell& cell) {
        if (cell.index >= letters.size()) {
            letters.resize(cell.index + 1);
            closures.resize(cell.index + 1);
        }
        if (cell.closed.empty() && cell.index != 0) {
            interior = cell.index;
        } else {
            auto& gens = closures[cell.index];
            gens.insert(gens.end(), cell.closure->begin(), cell.closure->end());
        }
        if (cell.index != 0) letters[cell.index] = cell.all_letters(n);
    });
    ModeSet out;
    out.feasible_twists = walk.feasible_twists();
    out.modes.resize(letters.size());
    for (std::size_t i = 0; i < letters.size(); ++i) {  // the letters moved, not copied: they are Theta(M n)
        if (i == interior && i != 0) {
            out.modes[i] = Mode{std::move(letters[i]), walk.feasible_twists()};
            continue;
        }
        std::vector<ExactVector> gens;
        for (const Q3& g : closures[i]) gens.push_back(ExactVector::from_exact(g));
        closures[i] = {};
        out.modes[i] = Mode{std::move(letters[i]), Cone::from_generators(gens)};
    }
    return out;
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
