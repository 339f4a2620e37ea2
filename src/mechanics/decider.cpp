// Decider (decider.hpp): certificates for the cells of the walk (Farkas planes and triangles of
// generators), mended by bridging and gift-wrapping steps, wide planes by Gilbert's algorithm,
// and E tested where none decides.
#include "decider.hpp"

#include <algorithm>
#include <cmath>

namespace momentlab::detail {
namespace {

// adj(m) w for a 3 x 3 matrix given by its rows: the columns of adj(m) are r1 x r2, r2 x r0,
// r0 x r1, so that m adj(m) = det(m) I.
Exact3 adjugate_times(const ExactMatrix& m, const Exact3& w) {
    return w[0] * cross(m[1], m[2]) + w[1] * cross(m[2], m[0]) + w[2] * cross(m[0], m[1]);
}

}  // namespace

Decider::Plane Decider::plane_of(const ExactVector& h) const {
    Plane p;
    p.h = h;
    p.rh = h.approximation();
    if (m_) {
        const Exact3 x = h.exact();
        const ExactMatrix& m = *m_;
        p.pulled = ExactVector::from_exact(x[0] * m[0] + x[1] * m[1] + x[2] * m[2]);
        p.rpulled = p.pulled.approximation();
    }
    return p;
}

bool Decider::holds_images(const Plane& p) const {
    if (!m_) return true;
    const std::vector<Exact3>& closure = *cell_->closure;
    const std::vector<ExactVector::Approximation>& rounded = filters_->of(closure);
    for (std::size_t i = 0; i < closure.size(); ++i) {
        if (dot_filtered(p.pulled, closure[i], p.rpulled, rounded[i]) == Sign::Negative) return false;
    }
    return true;
}

// h holds the generators (-edge) that the contact at position t adds.
bool Decider::holds_position(const Plane& p, std::size_t t) const {
    const auto j = static_cast<std::size_t>(cell_->closed[t]);
    return edges_.for_contact(j, cell_->letters[t], [&](const ExactVector& edge, int slot) {
        return side(p, edge, edges_.rounded(j, slot)) != Sign::Positive;
    });
}

// h holds the cell's generators other than the twists' images: every closed contact's, or
// the reduced ones of a grouped face (the same cone).
bool Decider::holds_edges(const Plane& p) const {
    if (!groups_) {
        for (std::size_t t = 0; t < cell_->closed.size(); ++t) {
            if (!holds_position(p, t)) return false;
        }
        return true;
    }
    return std::all_of(groups_->begin(), groups_->end(),
                       [&](const Generator& g) { return side(p, *g.vector, g.rounded) != Sign::Negative; });
}

char Decider::letter_of_contact(int j) const {
    const auto it = std::lower_bound(cell_->closed.begin(), cell_->closed.end(), j);
    if (it == cell_->closed.end() || *it != j) return letter(ContactMode::Separating);
    return cell_->letters[static_cast<std::size_t>(it - cell_->closed.begin())];
}

bool Decider::has_piece(const Piece& p) const {
    if (p.contact < 0) {  // the same twist among the cell's generators (along a face they recur as they are)
        return std::any_of(cell_->closure->begin(), cell_->closure->end(), [&](const Exact3& g) { return g == p.twist; });
    }
    const auto j = static_cast<std::size_t>(p.contact);
    const ContactGenerators has = contact_generators(letter_of_contact(p.contact));
    return std::any_of(has.begin(), has.end(), [&](FrictionEdge e) { return edges_.slot(j, e) == p.slot; });
}

bool Decider::decide() {
    if (is_zero(wrench_)) return true;  // in every closed cone
    if (cell_->closed.empty()) {
        // The interior of a full-dimensional A, where no contact touches: E = M A, and e is in
        // it when adj(M) e is in A (M is positive definite: adj(M) = det(M) M^-1, det > 0).
        // Quasi-static, E = {0}.
        current_valid_ = false;
        return m_ && a_.has(ExactVector::from_exact(adjugate_times(*m_, wrench_.exact())));
    }
    const auto inside = std::find_if(triangles_.begin(), triangles_.end(), [&](const std::array<Piece, 3>& t) {
        return has_piece(t[0]) && has_piece(t[1]) && has_piece(t[2]);
    });
    if (inside != triangles_.end()) {
        std::rotate(triangles_.begin(), inside, inside + 1);
        return true;
    }
    // The current plane: along a face's walk, only what changed since the previous cell.
    if (current_) {
        bool holds = holds_images(*current_);
        // (A cell the caller skips, one that joins the all-f mode, changes only contacts the
        // next cell of its face lists again; a new face starts over.)
        if (holds && current_valid_ && !cell_->first && cell_->face == last_face_) {
            for (int t : cell_->changed) holds = holds && holds_position(*current_, static_cast<std::size_t>(t));
        } else if (holds) {
            holds = holds_edges(*current_);  // (the images were checked above)
        }
        current_valid_ = holds;
        if (holds) return false;
    }
    if (cell_->closed.size() <= kSmallFace || groups_) {  // (a grouped face: a few generators)
        const auto found = std::find_if(planes_.begin(), planes_.end(), [&](const Plane& p) { return holds_cell(p); });
        if (found != planes_.end()) {
            current_ = *found;
            current_valid_ = true;
            std::rotate(planes_.begin(), found, found + 1);
            return false;
        }
    }
    if (groups_) {  // a few generators in place of the face's: no mend needed
        collect_images();
        for (const Generator& g : *groups_) generators_.push_back(g);
    } else {
        collect_generators();
    }
    if (!groups_ && cell_->closed.size() >= kMendFace) {
        scanned_ += generators_.size();
        if (const std::optional<bool> answer = mend()) {
            ++mended_;
            return *answer;
        }
    }
    if (std::optional<Plane> plane = wide_plane()) {
        keep_plane(std::move(*plane));
        return false;
    }
    return build();
}

// A mended certificate, the previous cell's kind first: the answer it gives, if one is.
std::optional<bool> Decider::mend() {
    if (last_member_ && mend_triangle()) return true;
    if (mend_plane()) return false;
    if (!last_member_ && mend_triangle()) return true;
    return std::nullopt;
}

// The cell's generators: the twists' images, then each closed contact's edges (position t's
// from first_[t]).
void Decider::collect_generators() {
    collect_images();
    first_.clear();
    for (std::size_t t = 0; t < cell_->closed.size(); ++t) {
        first_.push_back(generators_.size());
        const int j = cell_->closed[t];
        edges_.for_contact(static_cast<std::size_t>(j), cell_->letters[t], [&](const ExactVector& edge, int slot) {
            generators_.push_back({&edge, edges_.rounded(static_cast<std::size_t>(j), slot), true, j, slot, nullptr});
            return true;
        });
    }
    first_.push_back(generators_.size());
}

// The twists' images, the first generators of the cell.
void Decider::collect_images() {
    images_.clear();
    generators_.clear();
    if (!m_) return;
    for (const Exact3& r : *cell_->closure) images_.push_back(ExactVector::from_exact(r).transformed(*m_));
    for (std::size_t i = 0; i < images_.size(); ++i) {
        generators_.push_back({&images_[i], images_[i].approximation(), false, -1, 0, &(*cell_->closure)[i]});
    }
}

ExactVector Decider::vector_of(const Piece& p) const {
    if (p.contact < 0) return ExactVector::from_exact(p.twist).transformed(*m_);
    return edges_.edge(static_cast<std::size_t>(p.contact), p.slot).negated();
}

// The first generator of a contact that changed since the previous cell (of this face) for
// which `test` holds, if any.
template <class Test>
const Generator* Decider::changed_generator(Test test) const {
    if (cell_->first || cell_->face != last_face_) return nullptr;
    for (int t : cell_->changed) {
        const auto position = static_cast<std::size_t>(t);
        for (std::size_t i = first_[position]; i < first_[position + 1]; ++i) {
            if (test(generators_[i])) return &generators_[i];
        }
    }
    return nullptr;
}

// The latest triangle, some of its pieces gone. With two left, a and b in the triangle's
// cyclic order, a generator x of the cell in place of the third holds e when det(a, b, x) > 0,
// det(e, b, x) >= 0 and det(a, e, x) >= 0 (det(e, a, b) >= 0 held before and does not involve
// x). Else the bridge over e about each piece left, or about the cell's first generator when
// none is (or E had no triangle: it was not pointed).
bool Decider::mend_triangle() {
    std::array<Piece, 3> left{};
    std::size_t count = 0, gone = 0;
    if (!triangles_.empty()) {
        const std::array<Piece, 3>& t = triangles_.front();
        for (std::size_t k = 0; k < 3; ++k) {
            if (has_piece(t[k])) {
                left[count++] = t[k];
            } else {
                gone = k;
            }
        }
        // (in the triangle's cyclic order after the piece gone)
        if (count == 2 && gone == 1) std::swap(left[0], left[1]);
    }
    std::array<ExactVector, 2> kept;
    std::array<ExactVector::Approximation, 2> rounded;
    for (std::size_t k = 0; k < std::min<std::size_t>(count, 2); ++k) {
        kept[k] = vector_of(left[k]);
        rounded[k] = kept[k].approximation();
    }
    if (count == 2) {
        const ExactVector &a = kept[0], &b = kept[1];
        const ExactVector::Approximation re = wrench_.approximation();
        const auto completes = [&](const Generator& x) {
            return det_of(a, rounded[0], b, rounded[1], x) == Sign::Positive &&
                   det_of(wrench_, re, b, rounded[1], x) != Sign::Negative &&
                   det_of(a, rounded[0], wrench_, re, x) != Sign::Negative;
        };
        // (the contacts that changed first: along a face's walk the piece lost is theirs)
        const Generator* x = changed_generator(completes);
        if (!x) {
            const auto found = std::find_if(generators_.begin(), generators_.end(), completes);
            if (found != generators_.end()) x = &*found;
        }
        if (x) {
            keep_triangle({x->piece(), left[0], left[1]});
            return true;
        }
    }
    for (std::size_t k = 0; k < std::min<std::size_t>(count, 2); ++k) {
        if (bridge(kept[k], rounded[k], left[k])) return true;
    }
    if (count > 0 || generators_.empty()) return false;
    const Generator& first = generators_.front();
    const ExactVector p = first.negate ? first.vector->negated() : *first.vector;
    return bridge(p, p.approximation(), first.piece());
}

// A mended triangle in place of the latest one.
void Decider::keep_triangle(const std::array<Piece, 3>& t) {
    if (triangles_.empty()) {
        triangles_.push_back(t);
    } else {
        triangles_.front() = t;
    }
}

// e in cone(p, x, y) for a generator p of the cell: the plane through p and e splits the
// other generators into two sides, and e is in cone(p, x, y) for x, y on either side when the
// plane through x and y leaves p and e on one side. The pair that leaves the most there is the
// edge of E that the plane crosses beyond e; it is found as the bridge of two sets is, each
// taken as the tangent from the other in turn (a few rounds, each one scan of the cell's
// generators), and the triangle is then checked exactly.
bool Decider::bridge(const ExactVector& p, const ExactVector::Approximation& rp, const Piece& name) {
    constexpr int kRounds = 4;
    const Generator pg{&p, rp, false, 0, 0, nullptr};
    const Generator eg{&wrench_, wrench_.approximation(), false, 0, 0, nullptr};
    sides_.clear();
    const Generator* x = nullptr;  // det(p, e, x) > 0
    const Generator* y = nullptr;  // det(p, e, y) < 0
    // About p, x and y start as the generators nearest e on either side: the plane through
    // them crosses the ray of e (not its opposite) if any such plane does.
    for (const Generator& g : generators_) {
        sides_.push_back(det_of(pg, eg, g));
        if (sides_.back() == Sign::Positive && (!x || det_of(pg, g, *x) == Sign::Positive)) x = &g;
        if (sides_.back() == Sign::Negative && (!y || det_of(pg, g, *y) == Sign::Negative)) y = &g;
    }
    if (!x || !y || det_of(pg, *x, *y) != Sign::Negative) return false;
    // The tangent from `from` to the generators on side `on`: z replaces `to` when the plane
    // through from and to has z and p on opposite sides.
    const auto tangent = [&](const Generator& from, const Generator*& to, Sign on) {
        bool moved = false;
        Sign at_p = det_of(from, *to, pg);
        for (std::size_t i = 0; i < generators_.size(); ++i) {
            const Generator& z = generators_[i];
            if (sides_[i] != on || &z == to || at_p == Sign::Zero) continue;
            if (det_of(from, *to, z) == -at_p) {
                to = &z;
                at_p = det_of(from, *to, pg);
                moved = true;
            }
        }
        return moved;
    };
    for (int round = 0; round < kRounds; ++round) {
        const bool moved_y = tangent(*x, y, Sign::Negative);
        const bool moved_x = tangent(*y, x, Sign::Positive);
        if (!moved_x && !moved_y) break;
    }
    // e in cone(p, x, y): o = det(p, x, y) != 0, and det(e, x, y), det(p, e, y), det(p, x, e)
    // each of o's sign or 0.
    const Sign o = det_of(*x, *y, pg);
    if (o == Sign::Zero || det_of(*x, *y, eg) == -o || det_of(pg, eg, *y) == -o || det_of(pg, eg, *x) == o) return false;
    keep_triangle(o == Sign::Positive ? std::array<Piece, 3>{name, x->piece(), y->piece()}
                                      : std::array<Piece, 3>{name, y->piece(), x->piece()});
    return true;
}

// The current plane, broken by a generator g of the cell (one of the contacts that changed,
// if any does): of the planes through g and another generator x, the two with every generator
// on one side (found as gift wrapping finds its next edge, then checked exactly), one with e
// strictly on the other side is the cell's plane.
bool Decider::mend_plane() {
    if (!current_ || generators_.size() < 2) return false;
    const auto breaks = [&](const Generator& x) {
        const Sign s = side(*current_, *x.vector, x.rounded);
        return (x.negate ? -s : s) == Sign::Negative;
    };
    const Generator* g = changed_generator(breaks);
    if (!g) {
        const auto found = std::find_if(generators_.begin(), generators_.end(), breaks);
        if (found == generators_.end()) return false;
        g = &*found;
    }
    // The plane through g and x, turned so that e is on its negative side, when every
    // generator is on the other: h = side (g x x), h . y = side det(g, x, y) >= 0, h . e < 0.
    const Generator eg{&wrench_, wrench_.approximation(), false, 0, 0, nullptr};
    const auto through = [&](const Generator& x) {
        const Sign side = -det_of(*g, x, eg);
        if (side == Sign::Zero) return false;
        if (!std::all_of(generators_.begin(), generators_.end(), [&](const Generator& y) { return det_of(*g, x, y) != -side; })) {
            return false;
        }
        const int sign = (side == Sign::Positive ? 1 : -1) * (g->negate != x.negate ? -1 : 1);
        Plane plane = plane_of(ExactVector::cross(*g->vector, *x.vector, sign));
        plane.u = *g->vector;
        plane.v = *x.vector;
        plane.ru = g->rounded;
        plane.rv = x.rounded;
        plane.sign = sign;
        keep_plane(std::move(plane));
        return true;
    };
    // First about the generators the broken plane went through (the plane turns about one of
    // them along a face's walk), then about every generator: hi with det(g, hi, y) >= 0 for
    // every generator y if any has, lo with det(g, lo, y) <= 0 (one scan for both).
    if (current_->sign != 0) {
        const Plane old = *current_;
        if (through(Generator{&old.u, old.ru, false, 0, 0, nullptr}) || through(Generator{&old.v, old.rv, false, 0, 0, nullptr})) {
            return true;
        }
    }
    const Generator* hi = nullptr;
    const Generator* lo = nullptr;
    for (const Generator& y : generators_) {
        if (!hi) {
            if (!parallel(*g->vector, *y.vector)) hi = lo = &y;
            continue;
        }
        if (det_of(*g, *hi, y) == Sign::Negative) hi = &y;
        if (det_of(*g, *lo, y) == Sign::Positive) lo = &y;
    }
    return hi && (through(*hi) || through(*lo));
}

// e against E (its extreme rays from its generators); a new certificate either way.
bool Decider::build() {
    ++built_;
    if (groups_) ++grouped_;
    // The cell's generators as collect_generators lists them (each named there, for a
    // triangle that needs it).
    std::vector<ExactVector> generators;
    generators.reserve(generators_.size());
    for (const Generator& g : generators_) generators.push_back(g.negate ? g.vector->negated() : *g.vector);
    // Its facets are not built: only the one that separates, if any (cone_holds).
    tested_ += generators.size();
    const Held held = cone_holds(generators, wrench_);
    if (held.member) {
        if (held.triangle) remember_triangle(*held.triangle, generators);
        return true;
    }
    // A facet or equation of E with h . e < 0 (one exists: e is outside E).
    keep_plane(plane_of(held.separator));
    return false;
}

// A plane h in doubles with h . e < 0 and h . g >= 0 for every generator g of the cell, kept
// only when exactly checked: near the widest such plane, found in doubles as the point x of
// the hull of -e/|e| and the g/|g| nearest the origin (max over |h| = 1 of the least
// h . p is |x|, at h = x/|x|), by a few steps of Gilbert's algorithm. A facet of E has
// generators on it, which the generators of the next cell, turned a little, may cross; on
// the cradle of 10^5 contacts such planes made one walk build E 8 times as often.
std::optional<Decider::Plane> Decider::wide_plane() const {
    // (e scaled by a power of two first, so that |e|^2 neither underflows nor overflows)
    const double largest = e_.cwiseAbs().maxCoeff();
    if (!(largest > 0) || !std::isfinite(largest)) return std::nullopt;
    const Vec3 e = e_ * std::ldexp(1.0, -std::ilogb(largest));
    std::vector<Vec3>& points = points_;
    points.clear();
    points.push_back(-e / e.norm());
    for (const Generator& g : generators_) {
        const Vec3& a = g.rounded.approx;
        const double norm = a.norm();
        if (!(norm > 0) || !std::isfinite(norm)) continue;  // (zero, or out of range: the check decides)
        points.push_back(g.negate ? Vec3(-a / norm) : Vec3(a / norm));
    }
    // Each coordinate times a power of two s_k that brings its largest |p_k| to [1, 2), then
    // each point back to unit length: a scene 2^-40 long has torques 2^-40 times its forces,
    // and in the points as they are the widest plane's margin is about 2^-40 (turned down
    // below: one query on the tangent of 10^5 contacts then built E from 2 x 10^5 edges).
    // x found among the scaled points gives h = S x (h . g = x . S g, exactly).
    Vec3 scale = Vec3::Ones();
    for (int k = 0; k < 3; ++k) {
        double top = 0;
        for (const Vec3& p : points) top = std::max(top, std::fabs(p[k]));
        if (top > 0 && std::isnormal(top)) scale[k] = std::ldexp(1.0, -std::ilogb(top));
    }
    if (scale != Vec3::Ones()) {
        for (Vec3& p : points) {
            p = p.cwiseProduct(scale);
            p /= p.norm();
        }
    }
    Vec3 x = points.front();
    for (int step = 0; step < kWideSteps; ++step) {
        const Vec3* nearest = &points.front();
        double least = x.dot(*nearest);
        for (const Vec3& p : points) {
            const double d = x.dot(p);
            if (d < least) {
                least = d;
                nearest = &p;
            }
        }
        const double xx = x.squaredNorm();
        if (least >= 0.9 * xx) break;  // within 10% of the widest margin
        const Vec3 d = *nearest - x;
        x += std::clamp(-x.dot(d) / d.squaredNorm(), 0.0, 1.0) * d;
    }
    if (!(x.squaredNorm() > 1e-20)) return std::nullopt;
    const Vec3 h = x.cwiseProduct(scale);
    if (!h.allFinite()) return std::nullopt;
    Plane plane = plane_of(ExactVector::input(h));
    if (dot_sign(plane.h, wrench_) != Sign::Negative || !holds_cell(plane)) return std::nullopt;
    return plane;
}

// p as the current plane, and first in the cache.
void Decider::keep_plane(Plane p) {
    current_ = std::move(p);
    current_valid_ = true;
    planes_.insert(planes_.begin(), *current_);
    if (planes_.size() > kCache) planes_.pop_back();
}

// Keeps three generators of E whose cone holds e (corners: indices into generators, which
// are generators_ made vectors), named.
void Decider::remember_triangle(const std::array<std::size_t, 3>& corners, const std::vector<ExactVector>& generators) {
    std::array<Piece, 3> t;
    for (std::size_t corner = 0; corner < 3; ++corner) t[corner] = generators_[corners[corner]].piece();
    // Kept only when exactly checked: det(a, b, c) > 0 and w on the inner side of each face.
    const ExactVector &a = generators[corners[0]], &b = generators[corners[1]], &c = generators[corners[2]];
    if (det_sign(a, b, c) == Sign::Positive && det_sign(wrench_, b, c) != Sign::Negative &&
        det_sign(a, wrench_, c) != Sign::Negative && det_sign(a, b, wrench_) != Sign::Negative) {
        triangles_.insert(triangles_.begin(), t);
        if (triangles_.size() > kCache) triangles_.pop_back();
    }
}

}  // namespace momentlab::detail
