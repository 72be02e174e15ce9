// carom for Python: dense and jammed packings (carom/science/packing.hpp, contact_network.hpp) —
// the random start, the compression with its thermostat, and the contact network as arrays.
#include <pybind11/stl.h>

#include <optional>
#include <string>

#include "bindings.hpp"
#include "carom/science/contact_network.hpp"
#include "carom/science/packing.hpp"

namespace carom::python {
namespace {

Boundary packing_boundary(const std::string& name) {
  if (name == "periodic") return Boundary::periodic;
  if (name == "box") return Boundary::box;
  throw py::value_error("boundary must be \"periodic\" or \"box\", not \"" + name + "\"");
}

// Compresses with the GIL released; Ctrl-C stops it at the next window, with the world still
// growing (a compress call on it continues), and is raised once the world is consistent.
py::dict compress_world(const py::object& world_object, double rate, double eta, double kT,
                        double pressure_limit, std::uint64_t window_collisions,
                        std::uint64_t collision_limit) {
  World& world = unwrap_world(world_object);
  science::CompressionSettings settings;
  settings.rate = rate;
  settings.target_eta = eta;
  settings.kT = kT;
  settings.pressure_limit = pressure_limit;
  settings.window_collisions = window_collisions;
  settings.collision_limit = collision_limit;
  bool signalled = false;
  PyObject* type = nullptr;
  PyObject* value = nullptr;
  PyObject* traceback = nullptr;
  science::CompressionResult result;
  {
    const py::gil_scoped_release unlocked;
    result = science::compress(world, settings, [&](const science::CompressionProgress&) {
      const py::gil_scoped_acquire locked;
      if (PyErr_CheckSignals() != 0) {
        signalled = true;
        PyErr_Fetch(&type, &value, &traceback);
      }
      return signalled;
    });
  }
  if (signalled) {
    PyErr_Restore(type, value, traceback);
    throw py::error_already_set();
  }
  py::dict out;
  out["end"] = std::string(science::compression_end_name(result.end));
  out["jammed"] = result.jammed;
  out["eta"] = result.eta;
  out["pressure"] = result.pressure;
  out["collisions"] = result.collisions;
  out["windows"] = result.windows;
  out["thermostat_work"] = result.thermostat_work;
  out["time"] = result.time;
  return out;
}

py::dict contact_network(const py::object& world_object, std::optional<double> tolerance) {
  const World& world = unwrap_world(world_object);
  const double used = tolerance.value_or(science::kContactTolerance);
  const science::ContactNetwork network = science::find_contact_network(world, used);
  const auto n = static_cast<py::ssize_t>(network.contacts.size());
  py::array_t<std::uint32_t> pairs(
      {static_cast<py::ssize_t>(network.pairs.size()), py::ssize_t{2}});
  auto p = pairs.mutable_unchecked<2>();
  for (std::size_t k = 0; k < network.pairs.size(); ++k) {
    p(static_cast<py::ssize_t>(k), 0) = network.pairs[k].a;
    p(static_cast<py::ssize_t>(k), 1) = network.pairs[k].b;
  }
  py::array_t<std::uint32_t> contacts(n);
  py::array_t<bool> rattler(n);
  auto c = contacts.mutable_unchecked<1>();
  auto r = rattler.mutable_unchecked<1>();
  for (py::ssize_t i = 0; i < n; ++i) {
    c(i) = network.contacts[static_cast<std::size_t>(i)];
    r(i) = network.rattler[static_cast<std::size_t>(i)] != 0;
  }
  py::dict out;
  out["tolerance"] = used;
  out["pairs"] = pairs;
  out["contacts"] = contacts;
  out["rattler"] = rattler;
  out["rattlers"] = network.rattlers;
  out["wall_contacts"] = network.wall_contacts;
  out["Z"] = network.mean_contacts_of_rest;
  out["contacts_mean"] = network.mean_contacts;
  return out;
}

}  // namespace

void bind_packing(py::module_& m) {
  m.def(
      "make_packing_world",
      [](std::uint64_t n, std::optional<std::pair<double, double>> mix, const std::string& boundary,
         double aspect, double start_eta, double sized_for_eta, std::uint64_t seed) {
        science::PackingSpec spec;
        spec.n = n;
        if (mix) {
          spec.second_diameter = mix->first;
          spec.second_fraction = mix->second;
        }
        spec.boundary = packing_boundary(boundary);
        spec.aspect = aspect;
        spec.start_eta = start_eta;
        spec.sized_for_eta = sized_for_eta;
        spec.seed = seed;
        return wrap_world(science::make_packing_world(spec));
      },
      py::kw_only(), py::arg("n"), py::arg("mix") = py::none(), py::arg("boundary") = "periodic",
      py::arg("aspect") = 1.0, py::arg("start_eta") = 0.3, py::arg("sized_for_eta") = 0.84,
      py::arg("seed") = 1,
      "N disks (diameter 1, or mix = (D, F): diameter D for a fraction F) at random places at "
      "packing fraction start_eta, kT = 1, in a cell sized so that diameter 1 is at "
      "sized_for_eta (as carom pack starts)");
  m.def("compress", &compress_world, py::arg("world"), py::kw_only(), py::arg("rate") = 2e-3,
        py::arg("eta") = 0.0, py::arg("kT") = 1.0, py::arg("pressure_limit") = 1e12,
        py::arg("window_collisions") = 0, py::arg("collision_limit") = 0,
        "Lubachevsky-Stillinger compression of the world to packing fraction eta, or until "
        "jammed (eta = 0): the smallest diameter grows at rate thermal speeds; returns end, "
        "jammed, eta, pressure (Z = PA/NkT), collisions, windows, thermostat_work, time");
  m.def("contact_network", &contact_network, py::arg("world"), py::arg("tolerance") = py::none(),
        "Pairs within tolerance (default 1e-9) of touching, as indices into world.ids; each "
        "disk's contacts; the rattlers (removed iteratively); Z, the mean contacts of the rest");
  m.def(
      "psi6",
      [](const py::object& world, double cutoff) {
        return science::global_psi6(unwrap_world(world), cutoff);
      },
      py::arg("world"), py::arg("cutoff") = science::kPsi6Cutoff,
      "The global bond order |sum of psi6_j| / N, neighbours closer than cutoff times the "
      "sum of the two radii");
  m.def(
      "packing_fraction",
      [](const py::object& world) { return science::packing_fraction(unwrap_world(world)); },
      py::arg("world"), "Sum of pi r^2 over the balls divided by the cell's (or box's) area");
  m.def("contact_tolerance_at_pressure", &science::contact_tolerance_at_pressure, py::arg("z"),
        "The gap, in diameters, below which two disks of a packing at reduced pressure z count "
        "as touching (1e3 / z, at most 1e-2)");
}

}  // namespace carom::python
