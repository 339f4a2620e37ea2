// `momentlab stand SCENE [--gravity GX GY] [--tilt] [--json]`: will an assembly of bodies stand,
// how can it fall, how far can it be tilted (docs/assemblies.md).
#include <iostream>
#include <memory>

#include "common.hpp"
#include "momentlab/assembly/assembly_json.hpp"

namespace momentlab::cli {
namespace {

struct StandCommandOptions {
    std::string file;
    std::vector<TypedNumber> gravity;
    bool tilt = false;
    bool json = false;
};

std::string pair_text(const AssemblyContact& c) {
    return std::to_string(c.a) + "-" + (c.b == 0 ? std::string("world") : std::to_string(c.b));
}

std::string body_text(const Assembly& a, std::size_t k) {
    const std::string& name = a.bodies[k].name;
    return "body " + std::to_string(k + 1) + (name.empty() ? "" : " (" + printable(name) + ")");
}

std::string direction_text(const ExactDirection& d) {
    const auto coordinate = [&](std::size_t i) { return d.is_double[i] ? fmt(d.rounded[static_cast<int>(i)]) : d.exact[i]; };
    return "(" + coordinate(0) + ", " + coordinate(1) + ")";
}

void print_text(const Assembly& a, const StandResult& r) {
    const Equilibrium& e = r.equilibrium;
    std::cout << "can stand: " << (e.can_stand ? "yes" : "no") << "\n";
    if (e.can_stand) {
        std::cout << "  the contact forces of one equilibrium (on body a, at each contact a-b):\n";
        for (std::size_t j = 0; j < a.contacts.size(); ++j) {
            std::cout << "    contact " << j + 1 << " (" << pair_text(a.contacts[j]) << "): " << fmt(e.forces[j]) << "\n";
        }
    } else {
        std::cout << "  a collapse mechanism (every contact allows it, gravity does positive work):\n";
        for (std::size_t k = 0; k < e.mechanism.size(); ++k) {
            const BodyMotion& m = e.mechanism[k];
            std::cout << "    " << body_text(a, k) << ": twist " << fmt(m.twist);
            if (m.rotation_centre) {
                std::cout << ", turns about " << fmt(*m.rotation_centre);
            } else if (m.twist.x() != 0.0 || m.twist.y() != 0.0) {
                std::cout << ", translates";
            } else {
                std::cout << ", stays";
            }
            std::cout << "\n";
        }
    }
    if (r.modes) {
        std::cout << "modes (" << r.modes->modes.size() << ", " << to_string(r.modes->verdict) << "):";
        for (const std::string& m : r.modes->modes) std::cout << " " << m;
        std::cout << "\nmotions from rest:";
        if (r.modes->motions.empty()) std::cout << " none";
        for (const std::string& m : r.modes->motions) std::cout << " " << m;
        std::cout << "\noutcome: " << to_string(*r.outcome) << "\n";
    } else {
        std::cout << "modes: not enumerated (" << r.modes_reason << ")\n";
    }
    if (r.tilt) {
        std::cout << "tilt (the gravity vectors it stands under): " << to_string(r.tilt->kind);
        for (std::size_t i = 0; i < r.tilt->directions.size(); ++i) {
            std::cout << (i == 0 ? " " : " to ") << direction_text(r.tilt->directions[i]);
        }
        std::cout << "\n";
    }
}

int run(const StandCommandOptions& o) {
    InputWarnings warnings;
    const Assembly assembly = read_assembly_text(read_json_file(o.file), &warnings);
    for (const std::string& w : warnings) std::cerr << "momentlab: warning: " << printable(w) << "\n";
    StandOptions options;
    if (!o.gravity.empty()) {
        options.gravity = checked_points(o.gravity, "--gravity", 1).front();
    }
    options.tilt = o.tilt;
    const StandResult r = stand(assembly, options);
    if (o.json) {
        std::cout << to_json(r).dump() << "\n";
    } else {
        print_text(assembly, r);
    }
    return 0;
}

}  // namespace

std::function<int()> add_stand_command(CLI::App& app) {
    auto opts = std::make_shared<StandCommandOptions>();
    CLI::App* cmd = add_scene_command(app, opts, "stand",
                                      "Will an assembly of bodies stand, how can it fall, how far can it be tilted",
                                      "machine-readable output: {\"can_stand\", \"forces\" | \"mechanism\", \"modes\", ...}");
    cmd->add_option("--gravity", opts->gravity, "GX GY: gravity on every body at its centre of mass (default 0 -9.81)")
        ->expected(2, 2)
        ->transform(number_check());
    cmd->add_flag("--tilt", opts->tilt, "also the cone of gravity vectors for which it can stand");
    return [opts] { return run(*opts); };
}

}  // namespace momentlab::cli
