// The compiled part of the Python module (docs/python.md): the library's types as thin Python
// classes, numbers in and out as numpy arrays. Checks, messages and answers are the library's
// own: a scene given as Python values is read by read_scene, so a bad value raises ValueError
// with the same "$.path: message" line as the CLI. The friendlier API (keyword constructors,
// shapes, plots) is the pure-Python layer in python/momentlab.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cmath>
#include <limits>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "momentlab/assembly/assembly_json.hpp"
#include "momentlab/momentlab.hpp"
#include "values.hpp"

namespace py = pybind11;

namespace momentlab::python {
namespace {

// ---------------------------------------------------------------------------------------------
// An analysis: the scene's Problem (app/problem.hpp) with its analysis and index made.

struct Analysis {
    Problem problem;
    const std::vector<ModeForces>& modes;

    Analysis(Scene s, bool quasi_static) : problem(std::move(s), quasi_static), modes(problem.analysis("analyze")) {
        (void)problem.index();
    }

    const Scene& scene() const { return problem.scene(); }
    const ModeForces& mode(const std::string& letters) { return problem.goal(letters); }
};

// The modes of a batch of wrenches, one row per wrench, without the interpreter's lock.
py::array_t<bool> query_batch(Analysis& a, const py::handle& wrenches) {
    const std::vector<Vec3> w = vectors3_of(wrenches, "wrenches");
    const auto n = static_cast<py::ssize_t>(w.size());
    const auto m = static_cast<py::ssize_t>(a.modes.size());
    py::array_t<bool> out({n, m});
    bool* hit = out.mutable_data();
    const QueryIndex& index = a.problem.index();
    {
        py::gil_scoped_release unlocked;
        std::fill(hit, hit + n * m, false);
        std::vector<std::size_t> found;
        found.reserve(a.modes.size());
        for (py::ssize_t i = 0; i < n; ++i) {
            index.query(w[static_cast<std::size_t>(i)], found);
            for (std::size_t k : found) hit[i * m + static_cast<py::ssize_t>(k)] = true;
        }
    }
    return out;
}

// A wrench with its exact meaning (floats their binary values; Fractions, Decimals and strings
// as typed), its denominators cleared: a positive multiple, for cone membership.
ExactVector exact_wrench_of(const py::handle& w) {
    const Rational3 r = exact_vector_of<3>(w, "wrench");
    if (is_double(r)) return ExactVector::input(to_double(r));
    const std::vector<Dyadic> e = clear_denominators(r);
    return ExactVector::from_exact({e[0], e[1], e[2]});
}

// The vector, refused when zero (as the builders of doubles refuse it).
const Rational2& nonzero(const Rational2& v, const char* what) {
    if (v[0].is_zero() && v[1].is_zero()) throw std::invalid_argument(std::string(what) + " must be non-zero");
    return v;
}

// A load from the keyword arguments: gravity (GX, GY), wrench (FX, FY, TAU), forces [(point, force), ...].
Load load_of(const py::handle& gravity, const py::handle& wrench, const py::handle& forces = py::none()) {
    Load load;
    if (!gravity.is_none()) load.gravity = exact_vector_of<2>(gravity, "gravity");
    if (!wrench.is_none()) load.wrench = exact_vector_of<3>(wrench, "wrench");
    if (!forces.is_none()) {
        std::size_t i = 0;
        for (const auto& f : forces) {
            const std::string where = "forces[" + std::to_string(i++) + "]";
            const auto pair = py::reinterpret_borrow<py::sequence>(f);
            if (py::len(pair) != 2) throw InputError(where, "expected (point, force)");
            load.forces.emplace_back(exact_vector_of<2>(pair[0], where.c_str()), exact_vector_of<2>(pair[1], where.c_str()));
        }
    }
    return load;
}

std::string label_text(Label l) { return to_string(l); }

}  // namespace
}  // namespace momentlab::python

PYBIND11_MODULE(_momentlab, m) {
    using namespace momentlab;
    using namespace momentlab::python;
    m.doc() = "momentlab's compiled core; use the package `momentlab` (docs/python.md).";
    // The message the library gives a number that underflows (io/input_error.hpp), for the
    // checks made in Python (values.py).
    m.attr("TOO_SMALL_FOR_A_DOUBLE") = std::string(kTooSmallForADouble);

    py::class_<Region>(m, "Region", "One sheet of the moment labels: conv(vertices) + cone(rays) + span(lines).")
        .def_property_readonly("kind", &Region::kind)
        .def_property_readonly("is_empty", [](const Region& r) { return r.is_empty; })
        .def_property_readonly("vertices", [](const Region& r) { return rows<2>(r.vertices); },
                               "(k, 2) vertices (rounded)")
        .def_property_readonly("rays", [](const Region& r) { return rows<2>(r.rays); },
                               "(k, 2) directions in which the region is unbounded")
        .def_property_readonly("lines", [](const Region& r) { return rows<2>(r.lines); },
                               "(k, 2) directions of lines contained in the region")
        .def_property_readonly("halfplanes", [](const Region& r) { return rows<3>(r.halfplanes); },
                               "(k, 3) rows (a, b, c): a x + b y + c >= 0")
        .def(
            "clipped",
            [](const Region& r, const py::handle& box) {
                const Eigen::Vector4d b = vector_of<4>(box, "box");
                if (!(b(0) < b(2)) || !(b(1) < b(3))) throw InputError("box", "expected xmin < xmax and ymin < ymax");
                return rows<2>(r.clipped(Box{Vec2(b(0), b(1)), Vec2(b(2), b(3))}));
            },
            py::arg("box"), "The region cut to box = (xmin, ymin, xmax, ymax), as a (k, 2) polygon (for drawing).")
        .def("__repr__", [](const Region& r) { return "<Region " + r.kind() + ">"; });

    py::class_<Cone>(m, "Cone", "A closed polyhedral cone of wrenches (fx, fy, tau) or twists, exact.")
        .def_static(
            "from_generators", [](const py::handle& g) { return Cone::from_generators(vectors3_of(g, "generators")); },
            py::arg("generators"), "The non-negative combinations of the rows of an (n, 3) array.")
        .def_static(
            "from_halfspaces", [](const py::handle& h) { return Cone::from_halfspaces(vectors3_of(h, "normals")); },
            py::arg("normals"), "{w : n . w >= 0 for every row n}.")
        .def_static("zero", [] { return Cone(); })
        .def_static("whole_space", &Cone::whole_space)
        .def_property_readonly("rays", [](const Cone& c) { return rows<3>(c.rays()); })
        .def_property_readonly("lineality", [](const Cone& c) { return rows<3>(c.lineality()); })
        .def_property_readonly("facets", [](const Cone& c) { return rows<3>(c.facets()); },
                               "(k, 3) inward facet normals f: f . w >= 0")
        .def_property_readonly("equations", [](const Cone& c) { return rows<3>(c.equations()); })
        .def_property_readonly("generators", [](const Cone& c) { return rows<3>(c.generator_values()); },
                               "rays, then +- lineality vectors (rounded)")
        .def_property_readonly("halfspaces", [](const Cone& c) { return rows<3>(c.halfspace_values()); },
                               "facets, then +- equations (rounded)")
        .def_property_readonly("dimension", &Cone::dimension)
        .def_property_readonly("lineality_dimension", &Cone::lineality_dimension)
        .def_property_readonly("kind", &Cone::kind)
        .def_property_readonly("is_pointed", &Cone::is_pointed)
        .def_property_readonly("is_zero", &Cone::is_zero)
        .def("contains", [](const Cone& c, const py::handle& w) { return c.has(exact_wrench_of(w)); },
             py::arg("w"), "Exact membership of the wrench w (floats as their binary values; Fractions, Decimals and strings as typed).")
        .def("in_relative_interior", [](const Cone& c, const py::handle& w) { return c.in_relative_interior(exact_wrench_of(w)); },
             py::arg("w"))
        .def("dual", [](const Cone& c) { return c.dual(); })
        .def("negated", [](const Cone& c) { return c.negated(); })
        .def("issubset", [](const Cone& a, const Cone& b) { return subset(a, b); }, py::arg("other"))
        .def("__add__", [](const Cone& a, const Cone& b) { return sum(a, b); })
        .def("__and__", [](const Cone& a, const Cone& b) { return intersection(a, b); })
        .def("__neg__", [](const Cone& c) { return c.negated(); })
        .def("__eq__", [](const Cone& a, const Cone& b) { return a == b; })
        .def("labels", [](const Cone& c) { return Labels(c); }, "Its moment labels.")
        .def("__repr__", [](const Cone& c) {
            return "<Cone " + c.kind() + ", " + std::to_string(c.rays().size()) + " rays, " +
                   std::to_string(c.facets().size()) + " facets>";
        });

    py::class_<Labels>(m, "Labels", "The moment labels of a force set (Mason 1991, section 2).")
        .def(py::init<Cone>(), py::arg("forces"))
        .def("__repr__", [](const Labels& l) {
            return "<Labels: + " + l.plus().kind() + ", - " + l.minus().kind() + ">";
        })
        .def_property_readonly("forces", &Labels::forces)
        .def_property_readonly("plus", &Labels::plus)
        .def_property_readonly("minus", &Labels::minus)
        .def_property_readonly("both", [](const Labels& l) { return both_region(l.forces()); },
                               "the points about which every force has moment 0")
        .def("at", [](const Labels& l, const py::handle& p) { return label_text(l.at(exact_vector_of<2>(p, "point"))); },
             py::arg("point"), "The exact label of a point (floats their binary value; a Fraction, Decimal or numeric string as it reads): '+', '-', '+-' or 'none'.");

    py::class_<ModeForces>(m, "ModeSets", "One contact mode with its sets: twists A, F = M A, T and E.")
        .def_property_readonly("letters", [](const ModeForces& f) { return f.mode.letters; })
        .def_property_readonly("twists", [](const ModeForces& f) { return f.mode.twists; })
        .def_property_readonly("total", [](const ModeForces& f) { return f.total; }, "F_i = M A_i")
        .def_property_readonly("contact", [](const ModeForces& f) { return f.contact; }, "T_i")
        .def_property_readonly("applied", [](const ModeForces& f) { return f.applied; }, "E_i = F_i - T_i")
        .def("rotation_centres", [](const ModeForces& f) { return rotation_centres(f.mode); })
        .def("__repr__", [](const ModeForces& f) { return "<ModeSets " + f.mode.letters + ">"; });

    py::class_<Scene>(m, "_Scene")
        .def_static("from_json",
                    [](const std::string& text) {
                        InputWarnings warnings;
                        Scene s = read_scene_text(text, &warnings);
                        warn_all(warnings);
                        return s;
                    })
        .def_static("from_file",
                    [](const std::string& path) {
                        InputWarnings warnings;
                        Scene s = read_scene_text(read_json_file(path, "$"), &warnings);
                        warn_all(warnings);
                        return s;
                    })
        .def_static("from_doc",
                    [](const py::handle& doc) {
                        InputWarnings warnings;
                        Scene s = read_scene(json_of(doc, "$"), &warnings);
                        warn_all(warnings);
                        return s;
                    })
        .def("to_json", [](const Scene& s) { return to_json(s).dump(); })
        .def_property_readonly("has_body", [](const Scene& s) { return s.body.has_value(); })
        .def_property_readonly("mass", [](const Scene& s) { return s.body ? s.body->mass : 0.0; })
        .def_property_readonly("com", [](const Scene& s) { return s.body ? std::vector<double>{s.body->com.x(), s.body->com.y()} : std::vector<double>{}; })
        .def_property_readonly("inertia", [](const Scene& s) { return s.body ? s.body->inertia : 0.0; })
        .def_property_readonly("polygon", [](const Scene& s) { return rows<2>(s.body ? s.body->polygon : Polygon{}); })
        .def_property_readonly("obstacles", [](const Scene& s) {
            std::vector<Array> out;
            for (const Polygon& p : s.obstacles) out.push_back(rows<2>(p));
            return out;
        })
        .def_property_readonly("points", [](const Scene& s) {
            std::vector<Vec2> v;
            for (const Contact& c : s.contacts) v.push_back(c.point);
            return rows<2>(v);
        })
        .def_property_readonly("normals", [](const Scene& s) {
            std::vector<Vec2> v;
            for (const Contact& c : s.contacts) v.push_back(c.normal);
            return rows<2>(v);
        })
        .def_property_readonly("mu", [](const Scene& s) {
            std::vector<double> v;
            for (const Contact& c : s.contacts) v.push_back(c.mu);
            return py::array_t<double>(static_cast<py::ssize_t>(v.size()), v.data());
        })
        .def_property_readonly("mu_kinetic", [](const Scene& s) {
            std::vector<double> v;
            for (const Contact& c : s.contacts) v.push_back(c.mu_kinetic);
            return py::array_t<double>(static_cast<py::ssize_t>(v.size()), v.data());
        })
        .def_property_readonly("names", [](const Scene& s) {
            std::vector<std::string> v;
            for (const Contact& c : s.contacts) v.push_back(c.name);
            return v;
        });

    py::class_<Analysis, std::shared_ptr<Analysis>>(m, "_Analysis")
        .def(py::init<Scene, bool>())
        .def_property_readonly("scene", [](const Analysis& a) { return a.scene(); })
        .def_property_readonly("modes", [](const Analysis& a) {
            std::vector<std::string> out;
            for (const ModeForces& f : a.modes) out.push_back(f.mode.letters);
            return out;
        })
        .def("mode_at", [](const Analysis& a, std::size_t i) { return a.modes.at(i); }, py::return_value_policy::copy)
        .def("mode", [](Analysis& a, const std::string& letters) { return a.mode(letters); })
        .def("query_one",
             [](Analysis& a, const py::handle& wrench) { return a.problem.query(Load{.wrench = exact_vector_of<3>(wrench, "wrench")}).letters; })
        .def("margins",
             [](Analysis& a, const py::handle& wrench) {
                 const MarginAnswer m = a.problem.margins(Load{.wrench = exact_vector_of<3>(wrench, "wrench")});
                 py::dict inside;
                 for (std::size_t k = 0; k < m.answer.letters.size(); ++k) inside[py::str(m.answer.letters[k])] = m.inside[k];
                 py::dict out;
                 out["inside"] = inside;
                 out["to_other"] = m.to_other.value_or(std::numeric_limits<double>::infinity());
                 out["reference"] = std::vector<double>{m.metric.reference.x(), m.metric.reference.y()};
                 out["length"] = m.metric.length;
                 return out;
             })
        .def("query_batch", &query_batch)
        .def("plan_tilt",
             [](Analysis& a, const std::string& goal, const py::handle& wrench, const py::handle& forces) {
                 py::dict out = python_of(to_json(a.problem.plan_tilt(goal, load_of(py::none(), wrench, forces))));
                 out["goal"] = goal;
                 return out;
             })
        .def("plan_push",
             [](Analysis& a, const std::string& goal, const py::handle& mu, bool ignore_interference, const py::handle& gravity,
                const py::handle& wrench, const py::handle& forces) {
                 py::list out;
                 // mu exactly as given: a float its binary value, a Fraction, Decimal or string as it reads.
                 const Rational exact_mu = exact_vector_of<1>(py::make_tuple(mu), "mu")[0];
                 const PushRequest request{exact_mu, ignore_interference, std::nullopt, std::nullopt, std::nullopt};
                 for (const PushCase& c : a.problem.plan_push(goal, request, load_of(gravity, wrench, forces))) out.append(python_of(to_json(c)));
                 return out;
             })
        .def("plan_comply",
             [](Analysis& a, const std::string& goal, const py::handle& centre, const py::handle& gravity, const py::handle& wrench,
                const py::handle& forces) {
                 // the centre exactly as given: floats their binary value, a Fraction, Decimal or string as it reads
                 const std::optional<Rational2> at = centre.is_none() ? std::nullopt : std::optional<Rational2>(exact_vector_of<2>(centre, "centre"));
                 const ComplyAnswer answer = a.problem.plan_comply(goal, at, load_of(gravity, wrench, forces));
                 py::dict out;
                 out["goal"] = goal;
                 out["labels"] = python_of(to_json(answer.labels));  // plain data, as the CLI writes it
                 if (answer.centre) {
                     nlohmann::json centre_json = to_json(*answer.centre);
                     add_exact(centre_json, "point", *at);  // as the CLI's echo of a typed centre
                     out["centre"] = python_of(centre_json);
                 }
                 return out;
             })
        .def("push_line",
             [](Analysis& a, const py::handle& point, const py::handle& direction, const py::handle& gravity, const py::handle& wrench,
                const py::handle& forces) {
                 const Rational2 p = exact_vector_of<2>(point, "point");
                 const Rational2 d = exact_vector_of<2>(direction, "direction");
                 return python_of(to_json(a.problem.push_line(p, d, load_of(gravity, wrench, forces)), a.modes));
             });

    // Assemblies (docs/assemblies.md): read by read_assembly, answered by stand as `stand --json`.
    py::class_<Assembly>(m, "_Assembly")
        .def_static("from_json",
                    [](const std::string& text) {
                        InputWarnings warnings;
                        Assembly a = read_assembly_text(text, &warnings);
                        warn_all(warnings);
                        return a;
                    })
        .def_static("from_file",
                    [](const std::string& path) {
                        InputWarnings warnings;
                        Assembly a = read_assembly_text(read_json_file(path, "$"), &warnings);
                        warn_all(warnings);
                        return a;
                    })
        .def_static("from_doc",
                    [](const py::handle& doc) {
                        InputWarnings warnings;
                        Assembly a = read_assembly(json_of(doc, "$"), &warnings);
                        warn_all(warnings);
                        return a;
                    })
        .def_static("from_scene",
                    [](const Scene& s) {
                        if (!s.body) throw InputError("$", "missing field \"body\": an assembly needs the bodies' masses");
                        Assembly a = assembly_of(s);
                        check_assembly(a);
                        return a;
                    })
        .def_property_readonly("bodies", [](const Assembly& a) {
            py::list out;
            for (const AssemblyBody& b : a.bodies) {
                py::dict d;
                d["name"] = b.name;
                d["mass"] = b.mass;
                d["com"] = rows<2>(std::vector<Vec2>{b.com}).attr("reshape")(2);
                d["inertia"] = b.inertia ? py::object(py::float_(*b.inertia)) : py::object(py::none());
                d["radius_of_gyration"] = b.radius_of_gyration ? py::object(py::float_(*b.radius_of_gyration)) : py::object(py::none());
                d["polygon"] = rows<2>(b.polygon);
                out.append(d);
            }
            return out;
        })
        .def_property_readonly("pairs", [](const Assembly& a) {
            py::array_t<std::int64_t> out({static_cast<py::ssize_t>(a.contacts.size()), static_cast<py::ssize_t>(2)});
            auto r = out.mutable_unchecked<2>();
            for (std::size_t j = 0; j < a.contacts.size(); ++j) {
                r(static_cast<py::ssize_t>(j), 0) = static_cast<std::int64_t>(a.contacts[j].a);
                r(static_cast<py::ssize_t>(j), 1) = static_cast<std::int64_t>(a.contacts[j].b);
            }
            return out;
        })
        .def_property_readonly("points", [](const Assembly& a) {
            std::vector<Vec2> v;
            for (const AssemblyContact& c : a.contacts) v.push_back(c.contact.point);
            return rows<2>(v);
        })
        .def_property_readonly("normals", [](const Assembly& a) {
            std::vector<Vec2> v;
            for (const AssemblyContact& c : a.contacts) v.push_back(c.contact.normal);
            return rows<2>(v);
        })
        .def_property_readonly("mu", [](const Assembly& a) {
            std::vector<double> v;
            for (const AssemblyContact& c : a.contacts) v.push_back(c.contact.mu);
            return py::array_t<double>(static_cast<py::ssize_t>(v.size()), v.data());
        })
        .def_property_readonly("names", [](const Assembly& a) {
            std::vector<std::string> v;
            for (const AssemblyContact& c : a.contacts) v.push_back(c.contact.name);
            return v;
        })
        .def_property_readonly("obstacles", [](const Assembly& a) {
            std::vector<Array> out;
            for (const Polygon& p : a.obstacles) out.push_back(rows<2>(p));
            return out;
        });
    m.def("stand", [](const Assembly& a, const py::handle& gravity, bool tilt) {
        StandOptions options;
        if (!gravity.is_none()) options.gravity = exact_vector_of<2>(gravity, "gravity");
        options.tilt = tilt;
        return python_of(to_json(stand(a, options)));
    }, py::arg("assembly"), py::arg("gravity") = py::none(), py::arg("tilt") = false);

    // Force sets of the paper's Figure 1, their combinations and files.
    m.def("force", [](const py::handle& p, const py::handle& d) {
        const Rational2 point = exact_vector_of<2>(p, "point");  // in this order: the first bad argument is named
        const Rational2 direction = nonzero(exact_vector_of<2>(d, "direction"), "direction");
        return force_ray(point, direction);
    }, py::arg("point"), py::arg("direction"), "The positive multiples of one force through a point (Figure 1a).");
    m.def("line_of_force", [](const py::handle& p, const py::handle& d) {
        const Rational2 point = exact_vector_of<2>(p, "point");
        const Rational2 direction = nonzero(exact_vector_of<2>(d, "direction"), "direction");
        return line_of_force(point, direction);
    }, py::arg("point"), py::arg("direction"), "The forces along a line, both senses.");
    m.def("forces_through_point", [](const py::handle& p) {
        return forces_through_point(exact_vector_of<2>(p, "point"));
    }, py::arg("point"), "Every force whose line of action passes through the point (Figure 1b).");
    m.def("friction_cone", [](const py::handle& p, const py::handle& n, const py::handle& mu) {
        const Rational exact_mu = exact_vector_of<1>(py::make_tuple(mu), "mu")[0];
        if (exact_mu.sign() == Sign::Negative) throw InputError("mu", "expected a finite mu >= 0");
        const Rational2 point = exact_vector_of<2>(p, "point");
        const Rational2 normal = nonzero(exact_vector_of<2>(n, "normal"), "normal");
        return friction_cone(point, normal, exact_mu);
    }, py::arg("point"), py::arg("normal"), py::arg("mu"), "The Coulomb cone of a contact (Figure 1c).");
    m.def("closure", [](const Scene& scene, const py::handle& reference, std::optional<double> length) {
        const std::optional<Vec2> r = reference.is_none() ? std::nullopt : std::optional<Vec2>(vector_of<2>(reference, "reference"));
        return python_of(to_json(Problem(scene).closure(r, length)));
    }, py::arg("scene"), py::arg("reference") = py::none(), py::arg("length") = py::none());
    m.def("query", [](const Scene& scene, const py::handle& wrench, bool quasi_static, const py::handle& gravity,
                      const py::handle& forces) {
        Load load = load_of(gravity, py::none(), forces);
        if (!wrench.is_none()) load.wrench = exact_vector_of<3>(wrench, "wrench");
        const QueryAnswer a = Problem(scene, quasi_static).query(load);
        py::dict out;
        out["modes"] = a.letters;
        out["verdict"] = to_string(a.verdict);
        return out;
    }, py::arg("scene"), py::arg("wrench"), py::arg("quasi_static") = false, py::arg("gravity") = py::none(),
       py::arg("forces") = py::none());
    m.def("wrench", [](const py::handle& point, const py::handle& force) {
        const Vec2 p = vector_of<2>(point, "point");
        const Exact3 w = wrench_through(exact(p), exact(vector_of<2>(force, "force")));
        return std::vector<double>{to_double(w)[0], to_double(w)[1], to_double(w)[2]};
    }, py::arg("point"), py::arg("force"), "The wrench (fx, fy, tau about the origin) of a force acting through a point.");
    m.def("pure_moments", [](int sign) { return pure_moments(sign); }, py::arg("sign"));
    m.def("force_set_from_json", [](const std::string& text) {
        InputWarnings warnings;
        Cone c = read_force_set_text(text, &warnings);
        warn_all(warnings);
        return c;
    }, py::arg("text"), "A force set in the format of `momentlab label` (docs/formats.md).");
    m.def("find_contacts", [](const py::handle& body, const py::handle& obstacles, double distance, double mu,
                              std::optional<double> mu_kinetic) {
        const ContactFinding options{distance, mu, mu_kinetic.value_or(mu)};
        if (number_of(distance, "distance") < 0.0) throw InputError("distance", "expected a finite distance >= 0");
        if (number_of(mu, "mu") < 0.0 || number_of(options.mu_kinetic, "mu_kinetic") < 0.0) {
            throw InputError("mu", "expected finite friction coefficients >= 0");
        }
        std::vector<Polygon> fixed;
        std::size_t i = 0;
        for (const auto& o : obstacles) fixed.push_back(polygon_of(o, "obstacles[" + std::to_string(i++) + "]"));
        Scene found;
        found.contacts = find_contacts(polygon_of(body, "body"), fixed, options);
        return found;
    }, py::arg("body"), py::arg("obstacles"), py::arg("distance") = 1e-9, py::arg("mu") = 0.0,
       py::arg("mu_kinetic") = py::none(), "The contacts of a body polygon touching fixed polygons.");
}
