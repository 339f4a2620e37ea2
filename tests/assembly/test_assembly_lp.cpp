// The assembly layer's exact linear programs against cddlib's exact rational LP (GMP), which
// shares nothing with them: random small programs, a third of them degenerate on purpose
// (repeated and opposite columns, zero rows, rows that are sums of others, integer entries that
// meet exactly), and the counts of the decisions the intervals certified.
#include <gmpxx.h>
#include <gtest/gtest.h>
#include <setoper.h>
#include <cdd.h>

#include <mutex>
#include <random>

#include "../common/sizes.hpp"
#include "assembly/interval.hpp"
#include "assembly/linear_program.hpp"

namespace momentlab::assembly_detail {
namespace {

using testing::sized;

struct Case {
    int rows = 0;
    std::vector<std::vector<double>> a;  // by column
    std::vector<double> b;
    std::vector<bool> free, strict;
};

class Rng {
public:
    explicit Rng(std::uint64_t seed) : rng_(seed) {}
    int integer(int lo, int hi) { return lo + static_cast<int>(rng_() % static_cast<std::uint64_t>(hi - lo + 1)); }
    double unit() { return static_cast<double>(rng_() >> 11) * 0x1p-53; }

private:
    std::mt19937_64 rng_;
};

Case random_case(Rng& r, bool degenerate) {
    Case c;
    c.rows = r.integer(1, 6);
    const int n = r.integer(1, 9);
    for (int j = 0; j < n; ++j) {
        std::vector<double> col(static_cast<std::size_t>(c.rows));
        for (double& v : col) v = degenerate ? r.integer(-2, 2) : (r.unit() * 2 - 1) * (r.integer(0, 3) == 0 ? 0 : 1);
        if (degenerate && j > 0 && r.integer(0, 3) == 0) {  // a copy or an opposite of an earlier column
            col = c.a[static_cast<std::size_t>(r.integer(0, j - 1))];
            if (r.integer(0, 1)) {
                for (double& v : col) v = -v;
            }
        }
        c.a.push_back(col);
        c.free.push_back(r.integer(0, 4) == 0);
        c.strict.push_back(!c.free.back() && r.integer(0, 1) == 1);
    }
    c.b.resize(static_cast<std::size_t>(c.rows));
    const int kind = r.integer(0, 2);
    for (double& v : c.b) v = kind == 0 ? 0.0 : (degenerate ? r.integer(-3, 3) : r.unit() * 2 - 1);
    if (degenerate && c.rows > 1 && r.integer(0, 1)) {  // the last row the sum of the others
        for (auto& col : c.a) {
            double s = 0.0;
            for (int i = 0; i + 1 < c.rows; ++i) s += col[static_cast<std::size_t>(i)];
            col.back() = s;
        }
        double s = 0.0;
        for (int i = 0; i + 1 < c.rows; ++i) s += c.b[static_cast<std::size_t>(i)];
        c.b.back() = s;
    }
    return c;
}

template <class T>
Program<T> program(const Case& c, auto&& convert) {
    Program<T> p;
    p.rows = static_cast<std::uint32_t>(c.rows);
    for (std::size_t j = 0; j < c.a.size(); ++j) {
        SparseColumn<T> col;
        for (std::size_t i = 0; i < c.a[j].size(); ++i) {
            if (c.a[j][i] != 0.0) col.push_back({static_cast<std::uint32_t>(i), convert(c.a[j][i])});
        }
        p.add(std::move(col), c.free[j], c.strict[j]);
    }
    for (double v : c.b) p.rhs.push_back(convert(v));
    return p;
}

Program<Interval> enclosures(const Case& c) { return program<Interval>(c, [](double v) { return Interval(v); }); }
Program<Rational> exact(const Case& c) { return program<Rational>(c, [](double v) { return exact_value(v); }); }

// cddlib: max t over A x = b, x_j >= t (strict), x_j >= 0 (bounded), t <= 1 (t <= 0 when there
// is nothing strict); or max objective . x when `objective` is given. Returns the status and value.
struct CddAnswer {
    dd_LPStatusType status;
    mpq_class value;
};

CddAnswer cdd_solve(const Case& c, const std::vector<double>* objective) {
    static std::once_flag once;
    std::call_once(once, [] { dd_set_global_constants(); });
    const long n = static_cast<long>(c.a.size());
    long bounded = 0;
    for (long j = 0; j < n; ++j) bounded += c.free[static_cast<std::size_t>(j)] ? 0 : 1;
    const long rows = c.rows + bounded + 1;
    const long cols = n + 2;  // b, x..., t
    dd_MatrixPtr m = dd_CreateMatrix(rows, cols);
    m->representation = dd_Inequality;
    m->numbtype = dd_Rational;
    for (long r = 0; r < rows; ++r) {
        for (long k = 0; k < cols; ++k) dd_set_si(m->matrix[r][k], 0);
    }
    long r = 0;
    for (int i = 0; i < c.rows; ++i, ++r) {  // -b + A x = 0
        mpq_set(m->matrix[r][0], mpq_class(-c.b[static_cast<std::size_t>(i)]).get_mpq_t());
        for (long j = 0; j < n; ++j) {
            mpq_set(m->matrix[r][j + 1], mpq_class(c.a[static_cast<std::size_t>(j)][static_cast<std::size_t>(i)]).get_mpq_t());
        }
        set_addelem(m->linset, r + 1);
    }
    bool any_strict = false;
    for (long j = 0; j < n; ++j) {
        if (c.free[static_cast<std::size_t>(j)]) continue;
        dd_set_si(m->matrix[r][j + 1], 1);
        if (c.strict[static_cast<std::size_t>(j)] && !objective) {
            dd_set_si(m->matrix[r][n + 1], -1);
            any_strict = true;
        }
        ++r;
    }
    dd_set_si(m->matrix[r][0], any_strict ? 1 : 0);  // t <= 1
    dd_set_si(m->matrix[r][n + 1], -1);
    m->objective = dd_LPmax;
    for (long k = 0; k < cols; ++k) dd_set_si(m->rowvec[k], 0);
    if (objective) {
        for (long j = 0; j < n; ++j) mpq_set(m->rowvec[j + 1], mpq_class((*objective)[static_cast<std::size_t>(j)]).get_mpq_t());
    } else {
        dd_set_si(m->rowvec[n + 1], 1);
    }
    dd_ErrorType err = dd_NoError;
    dd_LPPtr lp = dd_Matrix2LP(m, &err);
    EXPECT_EQ(err, dd_NoError);
    dd_LPSolve(lp, dd_DualSimplex, &err);
    EXPECT_EQ(err, dd_NoError);
    CddAnswer out{lp->LPS, mpq_class(lp->optvalue)};
    dd_FreeLPData(lp);
    dd_FreeMatrix(m);
    return out;
}

std::string describe(const Case& c) {
    std::string s = "rows " + std::to_string(c.rows) + "\n";
    for (std::size_t j = 0; j < c.a.size(); ++j) {
        s += c.free[j] ? "free " : (c.strict[j] ? "strict " : "bounded ");
        for (double v : c.a[j]) s += std::to_string(v) + " ";
        s += "\n";
    }
    s += "b ";
    for (double v : c.b) s += std::to_string(v) + " ";
    return s;
}

bool has_strict(const Case& c) {
    for (std::size_t j = 0; j < c.a.size(); ++j) {
        if (c.strict[j]) return true;
    }
    return false;
}

TEST(LinearProgram, FeasibilityAgreesWithCddOnRandomPrograms) {
    Rng r(20261201);
    lp_counts() = {};
    int agree = 0, infeasible = 0, strictly = 0, boundary = 0;
    const int count = sized(3000);
    for (int k = 0; k < count; ++k) {
        const Case c = random_case(r, k % 3 == 0);
        const FeasibilityAnswer a = decide(enclosures(c), [&] { return exact(c); });
        const CddAnswer o = cdd_solve(c, nullptr);
        Feasibility expected = Feasibility::Infeasible;
        if (o.status == dd_Optimal && sgn(o.value) >= 0) {  // cdd's t is free: t < 0 is infeasible
            expected = (sgn(o.value) > 0 || !has_strict(c)) ? Feasibility::StrictlyFeasible : Feasibility::Feasible;
        } else if (o.status != dd_Optimal) {
            ASSERT_EQ(o.status, dd_Inconsistent) << "case " << k;
        }
        ASSERT_EQ(a.status, expected) << "case " << k << " exact path " << a.exact_path << "\n" << describe(c);
        if (a.status == Feasibility::Infeasible) {
            // The Farkas vector, rounded, still shows y . b > 0 clearly (a check of the output).
            double yb = 0.0;
            for (int i = 0; i < c.rows; ++i) yb += a.farkas[static_cast<std::size_t>(i)] * c.b[static_cast<std::size_t>(i)];
            EXPECT_GT(yb, 0.0) << "case " << k;
            ++infeasible;
        } else {
            for (int i = 0; i < c.rows; ++i) {  // the point, rounded, nearly satisfies A x = b
                double s = -c.b[static_cast<std::size_t>(i)];
                for (std::size_t j = 0; j < c.a.size(); ++j) s += c.a[j][static_cast<std::size_t>(i)] * a.point[j];
                EXPECT_NEAR(s, 0.0, 1e-9) << "case " << k;
            }
            (a.status == Feasibility::StrictlyFeasible ? strictly : boundary) += 1;
        }
        ++agree;
    }
    EXPECT_EQ(agree, count);
    EXPECT_GT(infeasible, count / 10);
    EXPECT_GT(strictly, count / 10);
    EXPECT_GT(boundary, count / 20);
    // Most decisions are certified in interval arithmetic; the degenerate ones go exact.
    EXPECT_GT(lp_counts().certified, static_cast<std::size_t>(count) / 3);
    EXPECT_GT(lp_counts().exact, 0U);
    std::printf("infeasible %d, strictly feasible %d, feasible on the boundary %d; certified %zu, exact %zu\n",
                infeasible, strictly, boundary, lp_counts().certified, lp_counts().exact);
}

// The doubles see the midpoints only: a . x = 1 with a in [-1, 1/2] (exactly 1/2) looks infeasible
// with room (a's midpoint is -1/4), but a sign is read only from an interval that excludes 0, so
// neither Farkas certificate holds and the exact path finds x = 2.
TEST(LinearProgram, MidpointsThatLookInfeasibleAreCheckedInIntervals) {
    Program<Interval> enclosures;
    enclosures.rows = 1;
    enclosures.rhs = {Interval(1.0)};
    enclosures.add({{0, Interval(-1.0, 0.5)}});
    const FeasibilityAnswer a = decide(enclosures, [] {
        Program<Rational> p;
        p.rows = 1;
        p.rhs = {Rational(1)};
        p.add({{0, Rational(1) / 2}});
        return p;
    });
    EXPECT_EQ(a.status, Feasibility::StrictlyFeasible);
    EXPECT_TRUE(a.exact_path);
    ASSERT_EQ(a.point.size(), 1U);
    EXPECT_EQ(a.point[0], 2.0);
}

TEST(LinearProgram, OptimaAgreeWithCddOnRandomPrograms) {
    Rng r(777);
    int optimal = 0, unbounded = 0, infeasible = 0;
    const int count = sized(1500);
    for (int k = 0; k < count; ++k) {
        const Case c = random_case(r, k % 3 == 0);
        std::vector<double> objective(c.a.size(), 0.0);
        std::vector<std::pair<std::uint32_t, int>> sparse;
        for (std::size_t j = 0; j < c.a.size(); ++j) {
            const int v = r.integer(-1, 1);
            objective[j] = v;
            if (v != 0) sparse.push_back({static_cast<std::uint32_t>(j), v});
        }
        const Optimum a = maximize(enclosures(c), [&] { return exact(c); }, sparse);
        const CddAnswer f = cdd_solve(c, nullptr);  // feasible first: cdd may report unboundedness of the dual alone
        if (!(f.status == dd_Optimal && sgn(f.value) >= 0)) {
            ASSERT_EQ(a.status, Optimum::Status::Infeasible) << "case " << k;
            ++infeasible;
            continue;
        }
        const CddAnswer o = cdd_solve(c, &objective);
        if (o.status == dd_Optimal) {
            ASSERT_EQ(a.status, Optimum::Status::Optimal) << "case " << k;
            const mpq_class value(exact_text(a.value));
            ASSERT_EQ(value, o.value) << "case " << k;
            ++optimal;
        } else {
            ASSERT_TRUE(o.status == dd_DualInconsistent || o.status == dd_StrucDualInconsistent) << "case " << k;
            ASSERT_EQ(a.status, Optimum::Status::Unbounded) << "case " << k << "\n" << describe(c);
            ++unbounded;
        }
    }
    EXPECT_GT(optimal, count / 10);
    EXPECT_GT(unbounded, count / 20);
    EXPECT_GT(infeasible, count / 20);
}

// enclose_solution against exact rational elimination (GMP): banded systems of 40-300 rows with
// random 53-bit entries (whose double solution is not exact), diagonally dominant so that the
// exact elimination needs no pivoting; the exact solution lies inside every enclosure, which is
// narrow. A matrix with two equal columns is not shown regular.
TEST(LinearProgram, PreconditionedEnclosuresHoldTheExactSolution) {
    Rng r(77);
    int systems = 0, widest_exponent = -1100;
    for (const int m : {40, 120, 300}) {
        for (int trial = 0; trial < 3; ++trial) {
            const int band = 2;
            std::vector<std::vector<double>> a(static_cast<std::size_t>(m), std::vector<double>(static_cast<std::size_t>(m), 0.0));
            std::vector<double> b(static_cast<std::size_t>(m));
            for (int i = 0; i < m; ++i) {
                for (int j = std::max(0, i - band); j <= std::min(m - 1, i + band); ++j) {
                    a[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)] = i == j ? 4 + r.unit() : r.unit() - 0.5;
                }
                b[static_cast<std::size_t>(i)] = r.unit() - 0.5;
            }
            std::vector<SparseColumn<Interval>> columns(static_cast<std::size_t>(m));
            for (int j = 0; j < m; ++j) {
                for (int i = 0; i < m; ++i) {
                    const double v = a[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)];
                    if (v != 0.0) columns[static_cast<std::size_t>(j)].push_back({static_cast<std::uint32_t>(i), Interval(v)});
                }
            }
            std::vector<Interval> rhs;
            for (double v : b) rhs.emplace_back(v);
            const std::optional<std::vector<Interval>> x = enclose_solution(columns, rhs);
            ASSERT_TRUE(x) << m;
            // Exact: Gaussian elimination in the band (U keeps the upper band), then back substitution.
            std::vector<std::vector<mpq_class>> q(static_cast<std::size_t>(m), std::vector<mpq_class>(static_cast<std::size_t>(m)));
            std::vector<mpq_class> c(static_cast<std::size_t>(m));
            for (int i = 0; i < m; ++i) {
                for (int j = std::max(0, i - band); j <= std::min(m - 1, i + band); ++j) {
                    q[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)] = a[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)];
                }
                c[static_cast<std::size_t>(i)] = b[static_cast<std::size_t>(i)];
            }
            for (int k = 0; k < m; ++k) {
                const auto K = static_cast<std::size_t>(k);
                for (int i = k + 1; i <= std::min(m - 1, k + band); ++i) {
                    const auto I = static_cast<std::size_t>(i);
                    const mpq_class f = q[I][K] / q[K][K];
                    for (int j = k; j <= std::min(m - 1, k + band); ++j) q[I][static_cast<std::size_t>(j)] -= f * q[K][static_cast<std::size_t>(j)];
                    c[I] -= f * c[K];
                }
            }
            std::vector<mpq_class> exact(static_cast<std::size_t>(m));
            for (int k = m - 1; k >= 0; --k) {
                const auto K = static_cast<std::size_t>(k);
                mpq_class s = c[K];
                for (int j = k + 1; j <= std::min(m - 1, k + band); ++j) s -= q[K][static_cast<std::size_t>(j)] * exact[static_cast<std::size_t>(j)];
                exact[K] = s / q[K][K];
            }
            bool some_inexact = false;
            for (int k = 0; k < m; ++k) {
                const Interval& v = (*x)[static_cast<std::size_t>(k)];
                const mpq_class& e = exact[static_cast<std::size_t>(k)];
                EXPECT_TRUE(mpq_class(v.lo) <= e && e <= mpq_class(v.hi)) << m << " " << k;
                some_inexact = some_inexact || mpq_class(v.mid()) != e;
                int exponent = 0;
                (void)std::frexp(v.hi - v.lo, &exponent);
                widest_exponent = std::max(widest_exponent, exponent);
            }
            EXPECT_TRUE(some_inexact);  // the doubles alone would not do
            ++systems;
        }
    }
    EXPECT_EQ(systems, 9);
    EXPECT_LT(widest_exponent, -30);  // narrow: widths below 2^-30
    // Two equal columns: singular, not shown regular.
    std::vector<SparseColumn<Interval>> singular = {{{0, Interval(1.0)}, {1, Interval(2.0)}}, {{0, Interval(1.0)}, {1, Interval(2.0)}}};
    EXPECT_FALSE(enclose_solution(singular, {Interval(1.0), Interval(1.0)}));
}

// A decimal that is not a double (0.1 as typed) enters the interval programs as an interval that
// holds it: shrunk to its rounding, the exact value would lie outside. Decimals of 1..19 digits
// and their negatives, checked with GMP against the interval's ends.
TEST(Interval, DecimalsAreEnclosed) {
    Rng r(2026);
    int strict = 0;
    for (int trial = 0; trial < 2000; ++trial) {
        const int digits = r.integer(1, 19), scale = r.integer(0, 25);
        std::string text = trial % 2 ? "-" : "";
        for (int i = 0; i < digits; ++i) text += static_cast<char>('0' + r.integer(i == 0 ? 1 : 0, 9));
        text += "e-" + std::to_string(scale);
        const std::optional<momentlab::Rational> x = momentlab::Rational::parse(text);
        ASSERT_TRUE(x) << text;
        const Interval i = enclose(*x);
        mpq_class exact(std::string(text.substr(0, text.find('e'))));
        mpz_class ten;
        mpz_ui_pow_ui(ten.get_mpz_t(), 10, static_cast<unsigned long>(scale));
        exact /= ten;
        EXPECT_LE(mpq_class(i.lo), exact) << text;
        EXPECT_GE(mpq_class(i.hi), exact) << text;
        strict += mpq_class(i.lo) < exact && exact < mpq_class(i.hi);
    }
    EXPECT_GT(strict, 1500);  // most are not doubles: strictly inside
}

}  // namespace
}  // namespace momentlab::assembly_detail
