// The one-shot path of query (mechanics/analysis.hpp, query.hpp): one question about a new scene
// of 2 to 12 contacts, answered in double arithmetic with certified error bounds; the exact path
// (query_scene) takes over wherever a sign is not certified (docs/robustness.md, "One question
// about a new scene").
//
// Every number is a certified approximation (core/approx.hpp, the filters' one number type): a
// double standing for the exact value x (a polynomial in the input numbers) with a bound on
// |x - value| that its operations compute; a sign is used only where that bound certifies it.
//
// The modes are those of enumerate_modes, for a generic scene: the face lattice of
// A = {xi : N_j . xi >= 0} cut by the lines T_j . xi = 0. With two contacts A is a wedge times
// the line L = N_1 x N_2; with three or more it is {0} or a pointed cone whose rays are the
// +-(N_a x N_b) on the positive side of every other N_k. Each facet {N_a . xi = 0} of A is cut
// where T_a . xi = 0, along the twist (p.y, -p.x, 1) that rotates about the contact point. A
// mode's E is the cone of the images M r of its closure's generators and the negated friction
// edges of its closed contacts; e is in it when three generators hold e strictly inside their
// simplicial cone, and out of it when the plane of two generators has every other generator
// strictly on one side and e strictly on the other (Farkas). Any sign left undecided (exact
// degeneracies, e on a boundary) sends the scene to the exact path.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "contact_model.hpp"
#include "momentlab/core/approx.hpp"
#include "query.hpp"

namespace momentlab {
namespace {

struct Uncertain {};  // a sign the bounds do not decide: the exact path answers

// The certified sign of x (+1, -1) by its own bound (core/approx.hpp), or 0 when the bound does
// not decide it.
int sign_or_zero(const Approx& x) {
    Sign s = Sign::Zero;
    if (!certified_sign(x, s)) return 0;
    return s == Sign::Positive ? 1 : -1;
}
// The certified sign of x; throws Uncertain when its bound does not decide it.
int sign_of(const Approx& x) {
    const int s = sign_or_zero(x);
    if (s == 0) throw Uncertain{};
    return s;
}

using A3 = std::array<Approx, 3>;

A3 input(double x, double y, double z) { return {Approx::exact(x), Approx::exact(y), Approx::exact(z)}; }
Approx dot(const A3& a, const A3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
A3 cross(const A3& a, const A3& b) { return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}; }
A3 negated(const A3& a) { return {-a[0], -a[1], -a[2]}; }
A3 signed_by(const A3& a, int s) { return s > 0 ? a : negated(a); }

struct Plain {
    double x, y, z;
};
Plain plain(const A3& a) { return {a[0].value, a[1].value, a[2].value}; }
double dot(const Plain& a, const Plain& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
Plain cross(const Plain& a, const Plain& b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }

constexpr std::size_t kMaxContacts = 12;
// Generators of one E: images of at most max(n, 4) twists and two friction edges per contact.
constexpr std::size_t kMaxGenerators = 2 * kMaxContacts + kMaxContacts;

// One generator of an E; `partner` is the index of its negation in the same list (a line), or -1.
struct Generator {
    A3 v;
    int partner = -1;
};

// Is e in cone(g[0..k))? Certified, or throws Uncertain. e is not zero.
bool contains(const Generator* g, std::size_t k, const A3& e) {
    const auto not_parallel = [&](const A3& a) {
        const A3 c = cross(a, e);
        return sign_or_zero(c[0]) != 0 || sign_or_zero(c[1]) != 0 || sign_or_zero(c[2]) != 0;
    };
    if (k == 0) return false;
    if (k == 1 || (k == 2 && g[0].partner == 1)) {
        if (not_parallel(g[0].v)) return false;
        throw Uncertain{};
    }
    if (k == 2) {
        if (sign_or_zero(dot(cross(g[0].v, g[1].v), e)) != 0) return false;  // e off their plane
        throw Uncertain{};
    }
    // Searched in plain doubles, then the one certificate found is checked with bounds.
    std::array<Plain, kMaxGenerators> p;
    for (std::size_t i = 0; i < k; ++i) p[i] = plain(g[i].v);
    const Plain pe = plain(e);
    // w[a][b] = p_a x p_b and we[a][b] = e . w[a][b] = det(p_a, p_b, e), for a < b.
    std::array<std::array<Plain, kMaxGenerators>, kMaxGenerators> w;
    std::array<std::array<double, kMaxGenerators>, kMaxGenerators> we;
    for (std::size_t a = 0; a < k; ++a) {
        for (std::size_t b = a + 1; b < k; ++b) {
            w[a][b] = cross(p[a], p[b]);
            we[a][b] = dot(pe, w[a][b]);
            we[b][a] = -we[a][b];
        }
    }
    const auto partners = [&](std::size_t a, std::size_t b) { return g[a].partner == static_cast<int>(b); };
    // Inside: det(a, b, c), det(e, b, c), det(a, e, c), det(a, b, e) of one strict sign.
    for (std::size_t a = 0; a < k; ++a) {
        for (std::size_t b = a + 1; b < k; ++b) {
            if (partners(a, b)) continue;
            for (std::size_t c = b + 1; c < k; ++c) {
                if (partners(a, c) || partners(b, c)) continue;
                const double d = dot(p[a], w[b][c]);
                const double d1 = we[b][c], d2 = we[c][a], d3 = we[a][b];
                const bool candidate = d > 0 ? d1 > 0 && d2 > 0 && d3 > 0 : d < 0 && d1 < 0 && d2 < 0 && d3 < 0;
                if (!candidate) continue;
                const A3 bc = cross(g[b].v, g[c].v);
                const int s = sign_or_zero(dot(g[a].v, bc));
                if (s != 0 && sign_or_zero(dot(e, bc)) == s && sign_or_zero(dot(e, cross(g[c].v, g[a].v))) == s &&
                    sign_or_zero(dot(e, cross(g[a].v, g[b].v))) == s) {
                    return true;
                }
            }
        }
    }
    // Outside: the plane of a and b with every other generator strictly on one side, e on the other.
    for (std::size_t a = 0; a < k; ++a) {
        for (std::size_t b = a + 1; b < k; ++b) {
            if (partners(a, b) || we[a][b] == 0.0) continue;
            const double side = we[a][b] > 0 ? -1.0 : 1.0;  // h = side (a x b): h . e < 0
            const auto on_plane = [&](std::size_t c) {
                return c == a || c == b || g[a].partner == static_cast<int>(c) || g[b].partner == static_cast<int>(c);
            };
            bool candidate = true;
            for (std::size_t c = 0; c < k && candidate; ++c) candidate = on_plane(c) || side * dot(w[a][b], p[c]) > 0;
            if (!candidate) continue;
            const A3 h = signed_by(cross(g[a].v, g[b].v), side > 0 ? 1 : -1);
            bool certified = sign_or_zero(dot(h, e)) == -1;
            for (std::size_t c = 0; c < k && certified; ++c) certified = on_plane(c) || sign_or_zero(dot(h, g[c].v)) == 1;
            if (certified) return false;
        }
    }
    throw Uncertain{};
}

// What the filtered path knows of one contact: N = (n, p x n), T = (t, p x t), the rotation
// about the contact point (p.y, -p.x, 1) (N . it = T . it = 0), and the negated friction edges
// -(d, p x d), d = n + c t, indexed by detail::FrictionEdge.
struct ContactData {
    A3 normal, tangent, about;
    std::array<A3, 4> edges;
};

constexpr std::array kEdges{detail::FrictionEdge::StaticPlus, detail::FrictionEdge::StaticMinus, detail::FrictionEdge::KineticPlus,
                            detail::FrictionEdge::KineticMinus};

ContactData contact_data(const Contact& c) {
    ContactData d;
    if (const ContactValues* values = c.exact_values()) {
        // Exact values: every vector times a positive number, its denominators cleared (the
        // point P / s, the normal's and mu's own), so the same signs.
        const detail::ClearedContact k = detail::cleared(*values);
        const Approx px = approximate(k.point[0]), py = approximate(k.point[1]), s = approximate(k.scale);
        const Approx nx = approximate(k.normal[0]), ny = approximate(k.normal[1]);
        d.normal = {s * nx, s * ny, px * ny - py * nx};
        d.tangent = {s * ny, -(s * nx), -(px * nx + py * ny)};
        d.about = {py, -px, s};
        for (const auto e : kEdges) {
            const Exact2 dir = detail::edge_direction(k, e);
            const Approx dx = approximate(dir[0]), dy = approximate(dir[1]);
            d.edges[static_cast<std::size_t>(e)] = negated(A3{s * dx, s * dy, px * dy - py * dx});
        }
        return d;
    }
    const Approx px = Approx::exact(c.point.x()), py = Approx::exact(c.point.y()), nx = Approx::exact(c.normal.x()),
                 ny = Approx::exact(c.normal.y());
    d.normal = {nx, ny, px * ny - py * nx};
    d.tangent = {ny, -nx, -(px * nx + py * ny)};
    d.about = input(c.point.y(), -c.point.x(), 1.0);
    for (const auto e : kEdges) {
        const auto [dx, dy] = friction_direction(nx, ny, Approx::exact(detail::tangent_coefficient(c, e)));
        d.edges[static_cast<std::size_t>(e)] = negated(A3{dx, dy, px * dy - py * dx});
    }
    return d;
}

// A mode found by the filtered enumeration: its letters and the generators of its closure
// (indices into the twist generators).
struct Draft {
    std::string letters;
    std::array<int, kMaxContacts> closure{};
    std::size_t size = 0;
};

char sliding(int s) { return s > 0 ? letter(ContactMode::SlidingRight) : letter(ContactMode::SlidingLeft); }

class Filtered {
public:
    Filtered(const Scene& scene, bool quasi_static) : n_(scene.contacts.size()) {
        for (const Contact& c : scene.contacts) {
            contacts_.push_back(contact_data(c));
            const ContactValues* values = c.exact_values();
            mu_zero_.push_back(values ? values->mu.is_zero() : c.mu == 0.0);
        }
        if (!quasi_static) {
            if (const BodyValues* values = scene.body->exact_values()) {
                const ExactMatrix m = detail::cleared_inertia(*values);
                for (std::size_t i = 0; i < 3; ++i) inertia_[i] = {approximate(m[i][0]), approximate(m[i][1]), approximate(m[i][2])};
            } else {
                inertia_ = detail::body_inertia<Approx>(*scene.body, Approx::exact);
            }
            dynamic_ = true;
        }
    }

    // Every mode (letters and closure), or throws Uncertain.
    void enumerate() {
        add(std::string(n_, letter(ContactMode::Fixed)), {});  // xi = 0
        if (n_ == 2) {
            two_contacts();
        } else {
            pointed();
        }
    }

    // The letters of the modes whose E holds e, or throws Uncertain.
    std::vector<std::string> holding(const Vec3& e) const {
        std::vector<std::string> out;
        const A3 w = input(e.x(), e.y(), e.z());
        const bool zero = is_zero(e);
        std::vector<A3> images;
        if (dynamic_) {
            for (const A3& t : twists_) images.push_back({dot(inertia_[0], t), dot(inertia_[1], t), dot(inertia_[2], t)});
        }
        std::array<Generator, kMaxGenerators> g;
        for (const Draft& d : modes_) {
            if (zero) {
                out.push_back(d.letters);
                continue;
            }
            std::size_t k = 0;
            if (dynamic_) {
                for (std::size_t i = 0; i < d.size; ++i) {
                    const auto t = static_cast<std::size_t>(d.closure[i]);
                    g[k] = Generator{images[t], -1};
                    for (std::size_t j = 0; j < i; ++j) {  // a line of the closure: +-t both in it
                        if (partner_[t] == d.closure[j]) g[k].partner = static_cast<int>(j), g[j].partner = static_cast<int>(k);
                    }
                    ++k;
                }
            }
            for (std::size_t j = 0; j < n_; ++j) {
                for (const detail::FrictionEdge edge : detail::contact_generators(d.letters[j])) {
                    // (the static cone is one edge when mu = 0: both are n)
                    if (edge == detail::FrictionEdge::StaticMinus && mu_zero_[j]) continue;
                    g[k++] = Generator{contacts_[j].edges[static_cast<std::size_t>(edge)], -1};
                }
            }
            if (contains(g.data(), k, w)) out.push_back(d.letters);
        }
        std::sort(out.begin(), out.end());
        return out;
    }

private:
    int twist(const A3& v, int partner = -1) {
        twists_.push_back(v);
        partner_.push_back(partner);
        if (partner >= 0) partner_[static_cast<std::size_t>(partner)] = static_cast<int>(twists_.size() - 1);
        return static_cast<int>(twists_.size() - 1);
    }

    void add(std::string letters, std::initializer_list<int> closure) {
        Draft d{std::move(letters), {}, 0};
        for (int i : closure) d.closure[d.size++] = i;
        modes_.push_back(std::move(d));
    }

    std::string separating() const { return std::string(n_, letter(ContactMode::Separating)); }

    // Two contacts: A is the wedge {N_1 . xi >= 0, N_2 . xi >= 0} times the line L = N_1 x N_2.
    void two_contacts() {
        const ContactData &c1 = contacts_[0], &c2 = contacts_[1];
        const A3 line = cross(c1.normal, c2.normal);
        const int t1 = sign_of(dot(c1.tangent, line)), t2 = sign_of(dot(c2.tangent, line));
        const int l = twist(line), minus_l = twist(negated(line), l);
        // Each facet {N_a . xi = 0} is a half-plane: the line and the rotation about contact a,
        // turned to the side where the other contact separates.
        const int h1 = twist(signed_by(c1.about, sign_of(dot(c2.normal, c1.about))));
        const int h2 = twist(signed_by(c2.about, sign_of(dot(c1.normal, c2.about))));
        add({sliding(t1), sliding(t2)}, {l});
        add({sliding(-t1), sliding(-t2)}, {minus_l});
        for (int a = 0; a < 2; ++a) {
            const int t = a == 0 ? t1 : t2, h = a == 0 ? h1 : h2;
            std::string s = separating();
            s[static_cast<std::size_t>(a)] = letter(ContactMode::Fixed);
            add(s, {h});
            s[static_cast<std::size_t>(a)] = sliding(t);
            add(s, {l, h});
            s[static_cast<std::size_t>(a)] = sliding(-t);
            add(s, {h, minus_l});
        }
        add(separating(), {l, minus_l, h1, h2});
    }

    // Three or more contacts, no three N_j dependent: A is {0} or a pointed cone.
    void pointed() {
        struct Ray {
            int twist;
            std::size_t a, b;
        };
        std::vector<Ray> rays;
        std::array<std::array<int, 2>, kMaxContacts> on{};  // the rays on contact j's facet
        std::array<int, kMaxContacts> count{};
        for (std::size_t a = 0; a < n_; ++a) {
            for (std::size_t b = a + 1; b < n_; ++b) {
                const A3 u = cross(contacts_[a].normal, contacts_[b].normal);
                int side = 0;
                bool mixed = false, unsure = false;
                for (std::size_t k = 0; k < n_ && !mixed; ++k) {
                    if (k == a || k == b) continue;
                    const int s = sign_or_zero(dot(contacts_[k].normal, u));
                    if (s == 0) {
                        unsure = true;
                    } else if (side == 0) {
                        side = s;
                    } else {
                        mixed = s != side;
                    }
                }
                if (mixed) continue;
                if (unsure) throw Uncertain{};
                if (rays.size() == kMaxContacts || count[a] == 2 || count[b] == 2) throw Uncertain{};
                const int r = twist(signed_by(u, side));
                on[a][static_cast<std::size_t>(count[a]++)] = static_cast<int>(rays.size());
                on[b][static_cast<std::size_t>(count[b]++)] = static_cast<int>(rays.size());
                rays.push_back({r, a, b});
            }
        }
        if (rays.empty()) return;  // A = {0}: only xi = 0
        std::size_t facets = 0;
        for (std::size_t j = 0; j < n_; ++j) {
            if (count[j] == 1) throw Uncertain{};
            facets += count[j] == 2;
        }
        if (rays.size() < 3 || facets != rays.size()) throw Uncertain{};
        for (const Ray& r : rays) {
            std::string s = separating();
            s[r.a] = sliding(sign_of(dot(contacts_[r.a].tangent, twists_[static_cast<std::size_t>(r.twist)])));
            s[r.b] = sliding(sign_of(dot(contacts_[r.b].tangent, twists_[static_cast<std::size_t>(r.twist)])));
            add(s, {r.twist});
        }
        for (std::size_t a = 0; a < n_; ++a) {
            if (count[a] != 2) continue;
            const Ray &r1 = rays[static_cast<std::size_t>(on[a][0])], &r2 = rays[static_cast<std::size_t>(on[a][1])];
            const int s1 = sign_of(dot(contacts_[a].tangent, twists_[static_cast<std::size_t>(r1.twist)]));
            const int s2 = sign_of(dot(contacts_[a].tangent, twists_[static_cast<std::size_t>(r2.twist)]));
            std::string s = separating();
            if (s1 == s2) {
                s[a] = sliding(s1);
                add(s, {r1.twist, r2.twist});
                continue;
            }
            // T_a . xi changes sign across the facet: the rotation about contact a, turned into
            // the wedge (where the facet's other two contacts both separate), cuts it in two.
            const std::size_t b1 = r1.a == a ? r1.b : r1.a, b2 = r2.a == a ? r2.b : r2.a;
            const int side = sign_of(dot(contacts_[b1].normal, contacts_[a].about));
            const A3 c = signed_by(contacts_[a].about, side);
            if (sign_of(dot(contacts_[b2].normal, c)) != 1) throw Uncertain{};
            const int m = twist(c);
            s[a] = letter(ContactMode::Fixed);
            add(s, {m});
            s[a] = sliding(s1);
            add(s, {r1.twist, m});
            s[a] = sliding(s2);
            add(s, {m, r2.twist});
        }
        Draft inside{separating(), {}, 0};
        for (const Ray& r : rays) inside.closure[inside.size++] = r.twist;
        modes_.push_back(std::move(inside));
    }

    std::size_t n_;
    std::vector<ContactData> contacts_;
    std::vector<bool> mu_zero_;
    std::array<A3, 3> inertia_{};
    bool dynamic_ = false;
    std::vector<A3> twists_;
    std::vector<int> partner_;
    std::vector<Draft> modes_;
};

}  // namespace

std::optional<std::vector<std::string>> detail::one_shot(const Scene& scene, const Vec3& e, bool quasi_static) {
    const std::size_t n = scene.contacts.size();
    if (n < 2 || n > kMaxContacts) return std::nullopt;
    try {
        Filtered f(scene, quasi_static);
        f.enumerate();
        return f.holding(e);
    } catch (const Uncertain&) {
        return std::nullopt;
    }
}

}  // namespace momentlab
