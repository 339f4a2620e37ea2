// stand(): equilibrium, modes, outcome and tilt together (docs/assemblies.md).
#include "momentlab/assembly/stand.hpp"

namespace momentlab {

const char* to_string(Outcome outcome) {
    switch (outcome) {
        case Outcome::Stands: return "stands";
        case Outcome::MayFall: return "may fall";
        case Outcome::Falls: return "falls";
        case Outcome::Inconsistent: return "inconsistent";
    }
    return "inconsistent";
}

Outcome outcome_of(const Equilibrium& equilibrium, const AssemblyModes& modes) {
    if (modes.modes.empty()) return Outcome::Inconsistent;
    if (!equilibrium.can_stand) return Outcome::Falls;
    return modes.motions.empty() ? Outcome::Stands : Outcome::MayFall;
}

StandResult stand(const Assembly& assembly, const StandOptions& options) {
    check_assembly(assembly);
    StandResult r;
    r.equilibrium = equilibrium(assembly, options.gravity);
    bool inertia = true;
    for (const AssemblyBody& b : assembly.bodies) inertia = inertia && (b.inertia || b.radius_of_gyration);
    if (assembly.contacts.size() > options.mode_contacts_limit) {
        r.modes_reason = std::to_string(assembly.contacts.size()) + " contacts: the modes are enumerated up to " +
                         std::to_string(options.mode_contacts_limit) + " (the letter strings grow as 4^n)";
    } else if (!inertia) {
        r.modes_reason = "a body has no inertia (the modes need every body's)";
    } else {
        r.modes = assembly_modes(assembly, options.gravity);
        r.outcome = outcome_of(r.equilibrium, *r.modes);
    }
    if (options.tilt) r.tilt = tilt_cone(assembly);
    return r;
}

}  // namespace momentlab
