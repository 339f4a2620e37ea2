#include "lp_oracle.hpp"

#include "cdd_setup.hpp"

#include <optional>
#include <stdexcept>

namespace momentlab::oracle {
namespace {

// Row r of the LP in the variables (xi_1, xi_2, xi_3, t): b + a . x >= 0 (or = 0 if `equal`).
void set_row(dd_MatrixPtr m, long r, const QVec& a, int slack, int b, bool equal) {
    mpq_set_si(m->matrix[r][0], b, 1);
    for (int i = 0; i < 3; ++i) mpq_set(m->matrix[r][i + 1], a[static_cast<std::size_t>(i)].get_mpq_t());
    mpq_set_si(m->matrix[r][4], slack, 1);
    if (equal) set_addelem(m->linset, r + 1);
}

// The LP of `realisable`: maximise a slack t <= 1 on the strict conditions; the twist it finds
// when t > 0, or none. 'z' is N_j . xi = 0 alone (any sliding), used to prune.
std::optional<QVec> interior_twist(const std::vector<QVec>& n, const std::vector<QVec>& t, const std::string& labels) {
    cdd_setup();
    long rows = 1;  // t <= 1
    bool strict = false;
    for (char c : labels) {
        rows += c == 's' || c == 'z' ? 1 : 2;
        strict = strict || (c != 'f' && c != 'z');
    }
    if (!strict) return QVec{0, 0, 0};  // xi = 0
    dd_MatrixPtr m = dd_CreateMatrix(rows, 5);
    m->representation = dd_Inequality;
    m->numbtype = dd_Rational;
    long r = 0;
    set_row(m, r++, QVec{0, 0, 0}, -1, 1, false);
    for (std::size_t j = 0; j < labels.size(); ++j) {
        switch (labels[j]) {
            case 's': set_row(m, r++, n[j], -1, 0, false); break;
            case 'z': set_row(m, r++, n[j], 0, 0, true); break;
            case 'f':
                set_row(m, r++, n[j], 0, 0, true);
                set_row(m, r++, t[j], 0, 0, true);
                break;
            case 'r':
                set_row(m, r++, n[j], 0, 0, true);
                set_row(m, r++, t[j], -1, 0, false);
                break;
            default:
                set_row(m, r++, n[j], 0, 0, true);
                set_row(m, r++, reference::neg(t[j]), -1, 0, false);
                break;
        }
    }
    m->objective = dd_LPmax;
    for (int i = 0; i < 5; ++i) dd_set_si(m->rowvec[i], i == 4 ? 1 : 0);
    dd_ErrorType err = dd_NoError;
    dd_LPPtr lp = dd_Matrix2LP(m, &err);
    if (err != dd_NoError) throw std::runtime_error("cdd Matrix2LP failed");
    dd_LPSolve(lp, dd_DualSimplex, &err);
    if (err != dd_NoError) throw std::runtime_error("cdd LPSolve failed");
    std::optional<QVec> out;
    if (lp->LPS == dd_Optimal && mpq_sgn(lp->optvalue) > 0) {
        out = QVec{mpq_class(lp->sol[1]), mpq_class(lp->sol[2]), mpq_class(lp->sol[3])};
    }
    dd_FreeLPData(lp);
    dd_FreeMatrix(m);
    return out;
}

// The letter of contact j for the twist xi, from the definitions; 'x' when it penetrates.
char letter_of(const QVec& n, const QVec& t, const QVec& xi) {
    const int vn = sgn(reference::dot(n, xi)), vt = sgn(reference::dot(t, xi));
    if (vn < 0) return 'x';
    if (vn > 0) return 's';
    return vt == 0 ? 'f' : (vt > 0 ? 'r' : 'l');
}

}  // namespace

bool realisable(const std::vector<QVec>& n, const std::vector<QVec>& t, const std::string& labels) {
    return interior_twist(n, t, labels).has_value();
}

bool applied_in_mode(const QMat& m, const std::vector<QVec>& n, const std::vector<QVec>& t,
                     const std::vector<std::vector<QVec>>& contact_generators,
                     const std::string& labels, const QVec& e) {
    cdd_setup();
    std::vector<QVec> gens;
    for (const auto& list : contact_generators) gens.insert(gens.end(), list.begin(), list.end());
    const long k = static_cast<long>(gens.size());
    long rows = 3 + k;
    for (char c : labels) rows += c == 's' ? 1 : 2;
    const long cols = 1 + 3 + k;
    dd_MatrixPtr a = dd_CreateMatrix(rows, cols);
    a->representation = dd_Inequality;
    a->numbtype = dd_Rational;
    for (long r = 0; r < rows; ++r) {
        for (long c = 0; c < cols; ++c) dd_set_si(a->matrix[r][c], 0);
    }
    long r = 0;
    for (int i = 0; i < 3; ++i, ++r) {  // (M xi)_i - sum alpha g_i - e_i = 0
        const auto row = static_cast<std::size_t>(i);
        mpq_set(a->matrix[r][0], mpq_class(-e[row]).get_mpq_t());
        for (int j = 0; j < 3; ++j) mpq_set(a->matrix[r][1 + j], m[row][static_cast<std::size_t>(j)].get_mpq_t());
        for (long q = 0; q < k; ++q) {
            mpq_set(a->matrix[r][4 + q], mpq_class(-gens[static_cast<std::size_t>(q)][row]).get_mpq_t());
        }
        set_addelem(a->linset, r + 1);
    }
    for (long q = 0; q < k; ++q, ++r) dd_set_si(a->matrix[r][4 + q], 1);  // alpha >= 0
    auto twist_row = [&](const QVec& v, int s, bool equal) {
        for (int j = 0; j < 3; ++j) mpq_set(a->matrix[r][1 + j], mpq_class(s * v[static_cast<std::size_t>(j)]).get_mpq_t());
        if (equal) set_addelem(a->linset, r + 1);
        ++r;
    };
    for (std::size_t j = 0; j < labels.size(); ++j) {
        switch (labels[j]) {
            case 's': twist_row(n[j], 1, false); break;
            case 'f': twist_row(n[j], 1, true); twist_row(t[j], 1, true); break;
            case 'r': twist_row(n[j], 1, true); twist_row(t[j], 1, false); break;
            default: twist_row(n[j], 1, true); twist_row(t[j], -1, false); break;
        }
    }
    a->objective = dd_LPmax;
    for (long c = 0; c < cols; ++c) dd_set_si(a->rowvec[c], 0);
    dd_ErrorType err = dd_NoError;
    dd_LPPtr lp = dd_Matrix2LP(a, &err);
    if (err != dd_NoError) throw std::runtime_error("cdd Matrix2LP failed");
    dd_LPSolve(lp, dd_DualSimplex, &err);
    if (err != dd_NoError) throw std::runtime_error("cdd LPSolve failed");
    const bool ok = lp->LPS == dd_Optimal;
    dd_FreeLPData(lp);
    dd_FreeMatrix(a);
    return ok;
}

std::set<std::string> all_modes(const std::vector<QVec>& n, const std::vector<QVec>& t) {
    // Depth-first over prefixes, each with a twist that realises it (the witness). A child whose
    // letter the witness already has is realisable with the same twist; the others take one LP
    // each, after one LP for N_j . xi = 0 alone, which rules out f, r and l together when the
    // contact must separate. Every witness is checked against its letters exactly.
    std::set<std::string> out;
    struct Node {
        std::string prefix;
        QVec xi;
    };
    std::vector<Node> stack = {{"", QVec{0, 0, 0}}};
    while (!stack.empty()) {
        const Node node = stack.back();
        stack.pop_back();
        const std::size_t j = node.prefix.size();
        for (std::size_t k = 0; k < j; ++k) {
            if (letter_of(n[k], t[k], node.xi) != node.prefix[k]) throw std::logic_error("all_modes: a witness does not realise its letters");
        }
        if (j == n.size()) {
            out.insert(node.prefix);
            continue;
        }
        const auto extend = [&](char c, const QVec& xi) {
            std::string next = node.prefix;
            next.push_back(c);  // (prefix + c trips GCC 12's -Wrestrict false positive)
            stack.push_back({std::move(next), xi});
        };
        const char own = letter_of(n[j], t[j], node.xi);
        const auto with = [&](char c) {
            std::string next = node.prefix;
            next.push_back(c);
            return next;
        };
        if (own == 's') {
            extend('s', node.xi);
        } else if (const auto xi = interior_twist(n, t, with('s'))) {
            extend('s', *xi);
        }
        // f, r, l: all need N_j . xi = 0.
        std::optional<QVec> on_plane;
        if (own != 's' && own != 'x') {
            on_plane = node.xi;
        } else {
            on_plane = interior_twist(n, t, with('z'));
        }
        if (!on_plane) continue;
        const char free = letter_of(n[j], t[j], *on_plane);
        for (char c : {'f', 'r', 'l'}) {
            if (c == free) {
                extend(c, *on_plane);
            } else if (const auto xi = interior_twist(n, t, with(c))) {
                extend(c, *xi);
            }
        }
    }
    return out;
}

}  // namespace momentlab::oracle
