// A downstream program: reads a scene (JSON) from the file named by the first argument, prints
// every contact mode, one per line, then the modes the applied wrench (fx, fy, tau) given by the
// next three arguments produces and the verdict. With no wrench, only the modes.
//
//   wheel_modes wheel.json 0 0 -1
#include <momentlab/momentlab.hpp>

#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>

int main(int argc, char** argv) {
    if (argc != 2 && argc != 5) {
        std::cerr << "usage: wheel_modes SCENE.json [FX FY TAU]\n";
        return 2;
    }
    std::ifstream in(argv[1]);
    std::stringstream text;
    text << in.rdbuf();
    try {
        const momentlab::Scene scene = momentlab::read_scene_text(text.str());
        const std::vector<momentlab::ModeForces> analysis = momentlab::analyze(scene);
        for (const momentlab::ModeForces& m : analysis) std::cout << m.mode.letters << '\n';
        if (argc == 5) {
            const momentlab::Vec3 e(std::strtod(argv[2], nullptr), std::strtod(argv[3], nullptr),
                                    std::strtod(argv[4], nullptr));
            const momentlab::QueryAnswer r = momentlab::query(scene, e);
            std::cout << "query:";
            for (const std::string& letters : r.letters) std::cout << ' ' << letters;
            std::cout << "\nverdict: " << momentlab::to_string(r.verdict) << '\n';
        }
    } catch (const std::exception& e) {
        std::cerr << "wheel_modes: " << e.what() << '\n';
        return 2;
    }
    return 0;
}
