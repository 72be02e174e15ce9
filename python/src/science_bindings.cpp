// carom for Python: the hard-disk gas measurements of `carom gas` and `carom eos`, through the
// tool's own option parsing, run and JSON report, so that Python and the command line give the
// same keys and, for the same arguments, the same numbers bit for bit.
#include <pybind11/stl.h>

#include <optional>
#include <string>
#include <vector>

#include "bindings.hpp"
#include "gas/gas_options.hpp"
#include "gas/gas_report.hpp"
#include "gas/gas_session.hpp"
#include "options/usage_error.hpp"
#include "pack/pack_session.hpp"

namespace carom::python {
namespace {

// The options as the command line would have them typed: str() of a Python number is the
// shortest text that reads back as the same double, so nothing is lost on the way.
cli::GasOptionText option_text(const py::object& n, const py::object& eta,
                               const py::object& equilibrate, const py::object& collisions,
                               const py::object& seed, const py::object& blocks,
                               const py::object& mix, const std::string& start) {
  cli::GasOptionText text;
  text.n = py::str(n);
  text.eta = py::str(eta);
  text.equilibrate = py::str(equilibrate);
  text.collisions = py::str(collisions);
  text.seed = py::str(seed);
  text.blocks = py::str(blocks);
  if (py::isinstance<py::str>(mix)) {
    text.mix = mix.cast<std::string>();
  } else if (!mix.is_none()) {
    const py::sequence pair = mix.cast<py::sequence>();
    if (pair.size() != 2) throw py::value_error("mix must be \"D:F\" or a pair (D, F)");
    text.mix = std::string(py::str(pair[0])) + ":" + std::string(py::str(pair[1]));
  }
  text.start = start;
  return text;
}

// A UsageError names a command-line option (--n); Python callers know the keyword (n).
[[noreturn]] void raise_usage(const cli::UsageError& error) {
  std::string name = error.option();
  if (name.rfind("--", 0) == 0) name.erase(0, 2);
  throw py::value_error(name + " = " + error.value() + ": " + error.problem());
}

py::object json_value(const std::string& text) {
  return py::module_::import("json").attr("loads")(text);
}

py::object gas(const py::object& n, const py::object& eta, const py::object& equilibrate,
               const py::object& collisions, const py::object& seed, const py::object& blocks,
               const py::object& mix, const std::string& start) {
  const cli::GasOptionText text =
      option_text(n, eta, equilibrate, collisions, seed, blocks, mix, start);
  cli::GasSpec spec;
  try {
    spec = cli::parse_gas_spec(text);
  } catch (const cli::UsageError& error) {
    raise_usage(error);
  }
  std::string json;
  {
    const py::gil_scoped_release unlocked;
    json = cli::gas_json(spec, cli::run_gas_session(spec)).dump();
  }
  return json_value(json);
}

py::object eos(const std::vector<py::object>& etas, const py::object& n,
               const py::object& equilibrate, const py::object& collisions, const py::object& seed,
               const py::object& blocks, const py::object& mix, const std::string& start) {
  const cli::GasOptionText text =
      option_text(n, py::float_(0.0), equilibrate, collisions, seed, blocks, mix, start);
  std::vector<cli::GasSpec> specs;
  try {
    for (const py::object& eta : etas) {
      specs.push_back(cli::parse_gas_spec(text, eta.cast<double>(), py::str(eta)));
    }
  } catch (const cli::UsageError& error) {
    raise_usage(error);
  }
  std::string json;
  {
    const py::gil_scoped_release unlocked;
    nlohmann::json points = nlohmann::json::array();
    for (const cli::GasSpec& spec : specs) {
      points.push_back(cli::gas_json(spec, cli::run_gas_session(spec)));
    }
    json = nlohmann::json{{"points", points}}.dump();
  }
  return json_value(json);
}

// A packing made as `carom pack --json` makes it. Ctrl-C stops it at the next window (the
// report then says end = "interrupted").
py::object pack(const py::object& n, const py::object& mix, const std::string& boundary,
                const py::object& aspect, const py::object& rate, const py::object& eta,
                const py::object& start_eta, const py::object& pressure_limit,
                const py::object& contact_tolerance, const py::object& seed) {
  cli::PackOptions o;
  o.n = py::str(n);
  if (py::isinstance<py::str>(mix)) {
    o.mix = mix.cast<std::string>();
  } else if (!mix.is_none()) {
    const py::sequence pair = mix.cast<py::sequence>();
    if (pair.size() != 2) throw py::value_error("mix must be \"D:F\" or a pair (D, F)");
    o.mix = std::string(py::str(pair[0])) + ":" + std::string(py::str(pair[1]));
  }
  o.boundary = boundary;
  o.aspect = py::str(aspect);
  o.rate = py::str(rate);
  o.until_jammed = eta.is_none();
  if (!eta.is_none()) o.eta = py::str(eta);
  o.start_eta = py::str(start_eta);
  o.pressure_limit = py::str(pressure_limit);
  if (!contact_tolerance.is_none()) o.tolerance = py::str(contact_tolerance);
  o.seed = py::str(seed);
  std::string json;
  try {
    const cli::PackRequest r = cli::parse_pack_options(o);
    bool signalled = false;
    {
      const py::gil_scoped_release unlocked;
      const cli::PackOutcome outcome =
          cli::run_pack_session(o, r, {}, [&signalled](const science::CompressionProgress&) {
            const py::gil_scoped_acquire locked;
            // The interrupt is raised once the world is consistent, below.
            if (!signalled && PyErr_CheckSignals() != 0) {
              signalled = true;
              PyErr_Clear();
            }
            return signalled;
          });
      json = cli::pack_json(o, r, outcome).dump();
    }
    if (signalled) {
      PyErr_SetNone(PyExc_KeyboardInterrupt);
      throw py::error_already_set();
    }
  } catch (const cli::UsageError& error) {
    raise_usage(error);
  }
  return json_value(json);
}

}  // namespace

void bind_science(py::module_& m) {
  m.def("pack", &pack, py::kw_only(), py::arg("n") = 1000, py::arg("mix") = py::none(),
        py::arg("boundary") = "periodic", py::arg("aspect") = 1.0, py::arg("rate") = 0.002,
        py::arg("eta") = py::none(), py::arg("start_eta") = 0.3, py::arg("pressure_limit") = 1e12,
        py::arg("contact_tolerance") = py::none(), py::arg("seed") = 1,
        "A packing as `carom pack --json` makes it (eta None: until jammed): the same dict");
  m.def("gas", &gas, py::arg("n") = 400, py::arg("eta") = 0.3, py::arg("equilibrate") = 50,
        py::arg("collisions") = 500, py::arg("seed") = 1, py::arg("blocks") = 16,
        py::arg("mix") = py::none(), py::arg("start") = "lattice",
        "A hard-disk gas measured as `carom gas --json` measures it: the same dict (NaN as None)");
  m.def("eos", &eos, py::arg("etas"), py::kw_only(), py::arg("n") = 400,
        py::arg("equilibrate") = 50, py::arg("collisions") = 500, py::arg("seed") = 1,
        py::arg("blocks") = 16, py::arg("mix") = py::none(), py::arg("start") = "lattice",
        "The equation of state at each packing fraction in etas, one after the other, as "
        "`carom eos --json`: {\"points\": [one gas() dict per point]}");
}

}  // namespace carom::python
