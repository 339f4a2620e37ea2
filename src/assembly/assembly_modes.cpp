// The contact modes of an assembly under gravity (docs/assemblies.md, "Modes"): a depth-first
// search over the letters contact by contact, each prefix kept only while (1) some twist of the
// bodies realises its letters (the cell is non-empty: one homogeneous program with the strict
// inequalities given a margin) and (2) the loads can be balanced with the twist in the closure of
// its cell, the contacts not yet lettered relaxed to the union of their letters (a program whose
// infeasibility rules out every completion). A complete string that passes both is a mode.
#include <optional>

#include "momentlab/core/parallel.hpp"

#include "assembly_programs.hpp"
#include "momentlab/assembly/stand.hpp"
#include "momentlab/io/input_error.hpp"

namespace momentlab {

using namespace assembly_detail;

namespace {

class ModeSearch {
public:
    // `d`, the enclosures of the assembly's programs, is shared by the searches of one call (the
    // threads only read it); each search builds the exact data when it first needs it.
    ModeSearch(const Assembly& assembly, const AssemblyData<Interval>& d, const Rational2& gravity,
               std::optional<bool> frictionless = std::nullopt)
        : assembly_(assembly), gravity_(gravity), d_(d), gx_(number<Interval>(gravity[0])), gy_(number<Interval>(gravity[1])),
          frictionless_(frictionless) {}

    const AssemblyData<assembly_detail::Rational>& exact() {
        if (!exact_) exact_ = assembly_data<assembly_detail::Rational>(assembly_);
        return *exact_;
    }
    assembly_detail::Rational egx() { return exact_value(gravity_[0]); }
    assembly_detail::Rational egy() { return exact_value(gravity_[1]); }

    bool cell_nonempty(const std::string& letters) {
        if (letters.find_first_not_of('f') == std::string::npos) return true;  // x = 0
        const FeasibilityAnswer a = decide(kinematic_program(d_, letters), [&] { return kinematic_program(exact(), letters); });
        return a.status == Feasibility::StrictlyFeasible;
    }

    bool loads_hold(const std::string& letters) {
        const FeasibilityAnswer a = decide(loads_program(d_, gx_, gy_, letters, false),
                                           [&] { return loads_program(exact(), egx(), egy(), letters, false); });
        return a.status != Feasibility::Infeasible;
    }

    bool passes(const std::string& prefix) { return (prefix.empty() || cell_nonempty(prefix)) && loads_hold(prefix); }

    void search(const std::string& prefix, std::vector<std::string>& modes) {
        if (passes(prefix)) below(prefix, modes);
    }

    // A program with one more row, x_i (times sign) minus a strict slack = 0, and only that
    // slack strict: some point of the program has sign * x_i > 0.
    template <class T>
    static Program<T> with_moving_coordinate(Program<T> p, Index i, int sign) {
        const Index row = p.rows++;
        p.rhs.push_back(number<T>(0.0));
        p.columns[i].push_back({row, number<T>(sign)});
        for (std::size_t j = 0; j < p.strict.size(); ++j) p.strict[j] = false;
        p.add({{row, number<T>(-1.0)}}, false, true);
        return p;
    }

    // The prefixes of up to `depth` letters that pass (and the modes shorter than that), in order.
    void prefixes(const std::string& prefix, std::size_t depth, std::vector<std::string>& out) {
        if (!passes(prefix)) return;
        if (prefix.size() == d_.contacts.size() || prefix.size() == depth) {
            out.push_back(prefix);
            return;
        }
        for (char letter : {'f', 's', 'r', 'l'}) prefixes(prefix + letter, depth, out);
    }

    // The modes that extend `prefix` (which passes), in order.
    void below(const std::string& prefix, std::vector<std::string>& modes) {
        if (prefix.size() == d_.contacts.size()) {
            modes.push_back(prefix);
            return;
        }
        for (char letter : {'f', 's', 'r', 'l'}) search(prefix + letter, modes);
    }

    // Accelerations in the mode's open cell with the loads balanced and some body moving. With a
    // letter s, r or l the open cell excludes x = 0; the all-f mode needs a coordinate of x that
    // can be non-zero: first in the kinematics (homogeneous), then with the loads.
    // With an equilibrium of normal forces alone (-G = sum nu_j N_j, nu >= 0) nothing can move
    // from rest, whatever the friction: a motion x from rest has x^T M x = G . x + (the contact
    // forces' power on x), where the power is 0 at s and f and <= 0 at r and l (friction opposes
    // sliding), and G . x = -sum nu_j N_j . d_j <= 0 since every N_j . d_j >= 0 in the closure;
    // so x^T M x <= 0 and x = 0 (docs/assemblies.md).
    bool frictionless_equilibrium() {
        if (!frictionless_) {
            const FeasibilityAnswer a = decide(equilibrium_program(d_, gx_, gy_, nullptr, true), [&] {
                return equilibrium_program(exact(), egx(), egy(), nullptr, true);
            });
            frictionless_ = a.status != Feasibility::Infeasible;
        }
        return *frictionless_;
    }

    bool has_motion(const std::string& letters) {
        if (frictionless_equilibrium()) return false;
        if (letters.find_first_not_of('f') != std::string::npos) {
            const FeasibilityAnswer a = decide(loads_program(d_, gx_, gy_, letters, true),
                                               [&] { return loads_program(exact(), egx(), egy(), letters, true); });
            return a.status == Feasibility::StrictlyFeasible;
        }
        for (Index i = 0; i < 3 * d_.bodies; ++i) {
            for (int sign : {1, -1}) {
                const FeasibilityAnswer k = decide(with_moving_coordinate(kinematic_program(d_, letters), i, sign), [&] {
                    return with_moving_coordinate(kinematic_program(exact(), letters), i, sign);
                });
                if (k.status != Feasibility::StrictlyFeasible) continue;
                const std::optional<std::pair<Index, int>> moving{{i, sign}};
                const FeasibilityAnswer l = decide(loads_program(d_, gx_, gy_, letters, true, moving), [&] {
                    return loads_program(exact(), egx(), egy(), letters, true, moving);
                });
                if (l.status == Feasibility::StrictlyFeasible) return true;
            }
        }
        return false;
    }

    const Assembly& assembly_;
    Rational2 gravity_;
    const AssemblyData<Interval>& d_;
    std::optional<AssemblyData<assembly_detail::Rational>> exact_;
    Interval gx_, gy_;
    std::optional<bool> frictionless_;
};

}  // namespace

AssemblyModes assembly_modes(const Assembly& assembly, const Rational2& gravity) {
    check_assembly(assembly);
    for (std::size_t k = 0; k < assembly.bodies.size(); ++k) {
        const AssemblyBody& b = assembly.bodies[k];
        if (!b.inertia && !b.radius_of_gyration) {
            throw InputError("$.bodies[" + std::to_string(k) + "]",
                             "missing field \"inertia\" (or \"radius_of_gyration\"): the modes need it");
        }
    }
    // The search tree below the prefixes of three letters (at most 64 subtrees) on up to two
    // threads, each with its own search (and exact data); the modes in the order of the letters.
    const AssemblyData<Interval> d = assembly_data<Interval>(assembly);
    ModeSearch top(assembly, d, gravity);
    std::vector<std::string> starts;
    top.prefixes(std::string(), 3, starts);
    const bool large = assembly.contacts.size() >= 6;
    std::vector<std::vector<std::string>> found(starts.size());
    detail::for_each_index(starts.size(), large, [&](std::size_t i) { ModeSearch(assembly, d, gravity).below(starts[i], found[i]); });
    AssemblyModes out;
    for (std::vector<std::string>& modes : found) out.modes.insert(out.modes.end(), modes.begin(), modes.end());
    out.verdict = verdict_of(out.modes.size());
    // With an equilibrium of normal forces alone nothing moves (has_motion); else each mode's
    // motion is looked for on up to two threads.
    std::vector<char> moves(out.modes.size(), 0);
    if (!top.frictionless_equilibrium()) {
        detail::for_each_index(out.modes.size(), large, [&](std::size_t i) {
            moves[i] = ModeSearch(assembly, d, gravity, false).has_motion(out.modes[i]);
        });
    }
    for (std::size_t i = 0; i < out.modes.size(); ++i) {
        if (moves[i]) out.motions.push_back(out.modes[i]);
    }
    return out;
}

}  // namespace momentlab
