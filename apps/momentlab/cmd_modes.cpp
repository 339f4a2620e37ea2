// `momentlab modes SCENE [--json]`: every kinematically feasible contact mode.
#include <iomanip>
#include <iostream>
#include <memory>

#include "common.hpp"

namespace momentlab::cli {
namespace {

struct ModesOptions {
    std::string file;
    bool json = false;
};

int run(const ModesOptions& o) {
    const Scene scene = read_scene_file(o.file);
    TerminalProgress progress;
    const ModeSet set = enumerate_modes(scene.contacts, progress.callback());
    progress.finish();
    if (o.json) {
        // Written as it goes (letters need no escaping), byte for byte what a JSON library's
        // compact dump gives, without a second copy of the Theta(modes x contacts) letters.
        const nlohmann::json found = found_contacts_json(scene);
        std::cout << "{";
        if (!found.empty()) std::cout << "\"found_contacts\":" << found.dump() << ",";
        std::cout << "\"modes\":[";
        for (std::size_t i = 0; i < set.modes.size(); ++i) {
            std::cout << (i ? ",\"" : "\"") << set.modes[i].letters << '"';
        }
        std::cout << "]}\n";
        return 0;
    }
    std::cout << found_contacts_text(scene) << set.modes.size() << " contact modes; feasible twists: " << set.feasible_twists.kind() << "\n";
    for (const Mode& m : set.modes) {
        std::cout << "  " << std::left << std::setw(static_cast<int>(scene.contacts.size()) + 2) << m.letters
                  << describe_mode(scene, m.letters) << "\n";
    }
    return 0;
}

}  // namespace

std::function<int()> add_modes_command(CLI::App& app) {
    auto opts = std::make_shared<ModesOptions>();
    add_scene_command(app, opts, "modes", "List every contact mode of a scene (s, f, r, l per contact)",
                      "machine-readable output: {\"found_contacts\": [...] (when found from the polygons), \"modes\": [...]}");
    return [opts] { return run(*opts); };
}

}  // namespace momentlab::cli
