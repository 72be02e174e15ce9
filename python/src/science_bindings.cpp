// carom for Python: the hard-disk gas measurements of `carom gas` and `carom eos`, through the
// tool's own option parsing, run and JSON report, so that Python and the command line give the
// same keys and, for the same arguments, the same numbers bit for bit.
#include <pybind11/stl.h>

#include <atomic>
#include <exception>
#include <filesystem>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "bindings.hpp"
#include "comm_job.hpp"
#include "gas/eos_sweep.hpp"
#include "gas/gas_options.hpp"
#include "gas/gas_points.hpp"
#include "gas/gas_report.hpp"
#include "gas/gas_session.hpp"
#include "gas/seed_ensemble.hpp"
#include "options/usage_error.hpp"
#include "pack/pack_ensemble.hpp"
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

// Ctrl-C while runs go without the GIL: watch() (told on the calling thread about ten times a
// second) looks for it, stop() answers it to every world, and raise_if_signalled() raises
// KeyboardInterrupt once the runs have returned.
class CtrlCWatch {
 public:
  [[nodiscard]] std::function<bool()> stop() {
    return [this] { return signalled_.load(); };
  }
  [[nodiscard]] std::function<void(double)> watch() {
    return [this](double) {
      const py::gil_scoped_acquire locked;
      if (PyErr_CheckSignals() != 0) {
        PyErr_Clear();
        signalled_.store(true);
      }
    };
  }
  void raise_if_signalled() const {
    if (!signalled_.load()) return;
    PyErr_SetNone(PyExc_KeyboardInterrupt);
    throw py::error_already_set();
  }

 private:
  std::atomic<bool> signalled_{false};
};

// Each of what `not_kept` lists as a RuntimeWarning (raised where warnings are made errors).
void warn_not_kept(const std::string& what, const std::vector<std::string>& not_kept) {
  for (const std::string& failure : not_kept) {
    std::string warning = what;
    warning += " was not kept: ";
    warning += failure;
    if (PyErr_WarnEx(PyExc_RuntimeWarning, warning.c_str(), 1) != 0) {
      throw py::error_already_set();
    }
  }
}

// Runs the points as `carom eos` runs them (gas/eos_sweep.hpp), shared among the job's processes,
// with checkpoints in `folder` unless it is empty, the GIL released. Ctrl-C stops every point
// within a few thousand events (the calling thread looks for it ten times a second) and raises
// KeyboardInterrupt; an error in a point is raised once all have stopped. Only at rank 0 are the
// outcomes returned.
std::optional<std::vector<cli::GasOutcome>> run_points(const std::vector<cli::GasSpec>& specs,
                                                       std::size_t threads,
                                                       const cli::EnsembleJob& job,
                                                       const std::string& folder) {
  CtrlCWatch ctrl_c;
  cli::EosSweepOutcome sweep;
  {
    const py::gil_scoped_release unlocked;
    sweep = cli::run_sweep(specs, threads, folder, ctrl_c.stop(), ctrl_c.watch(), job);
  }
  ctrl_c.raise_if_signalled();
  warn_not_kept("a finished run", sweep.not_kept);
  if (!sweep.leads) return std::nullopt;
  for (const std::exception_ptr& failure : sweep.runs.failures) {
    if (failure) std::rethrow_exception(failure);
  }
  return std::move(sweep.runs.outcomes);
}

// One run in this process alone, without checkpoints.
cli::GasOutcome run_alone(const cli::GasSpec& spec) {
  const cli::SingleProcessJob alone;
  return std::move(run_points({spec}, 1, alone, {})->front());
}

cli::GasSpec gas_spec(const py::object& n, const py::object& eta, const py::object& equilibrate,
                      const py::object& collisions, const py::object& seed,
                      const py::object& blocks, const py::object& mix, const std::string& start) {
  const cli::GasOptionText text =
      option_text(n, eta, equilibrate, collisions, seed, blocks, mix, start);
  try {
    return cli::parse_gas_spec(text);
  } catch (const cli::UsageError& error) {
    raise_usage(error);
  }
}

py::object gas(const py::object& n, const py::object& eta, const py::object& equilibrate,
               const py::object& collisions, const py::object& seed, const py::object& blocks,
               const py::object& mix, const std::string& start) {
  const cli::GasSpec spec = gas_spec(n, eta, equilibrate, collisions, seed, blocks, mix, start);
  return json_value(cli::gas_json(spec, run_alone(spec)).dump());
}

// An (x, y) curve as a pair of arrays.
py::tuple curve_arrays(const science::Curve& curve) {
  return py::make_tuple(
      py::array_t<double>(static_cast<py::ssize_t>(curve.x.size()), curve.x.data()),
      py::array_t<double>(static_cast<py::ssize_t>(curve.y.size()), curve.y.data()));
}

// What gas() reports, with the distributions and the last configuration it measured as arrays.
struct GasMeasurement {
  py::object report;
  py::tuple rdf, speed, psi6_local, msd;
  py::array positions, radii, psi6_modulus, psi6_angle;
};

GasMeasurement measure_gas(const py::object& n, const py::object& eta,
                           const py::object& equilibrate, const py::object& collisions,
                           const py::object& seed, const py::object& blocks, const py::object& mix,
                           const std::string& start) {
  const cli::GasSpec spec = gas_spec(n, eta, equilibrate, collisions, seed, blocks, mix, start);
  const cli::GasOutcome outcome = run_alone(spec);
  const science::GasResults& r = outcome.results;
  GasMeasurement m;
  m.report = json_value(cli::gas_json(spec, outcome).dump());
  m.rdf = curve_arrays(r.rdf);
  m.speed = curve_arrays(r.speed);
  m.psi6_local = curve_arrays(r.psi6_local);
  m.msd = curve_arrays(r.msd);
  py::array_t<double> positions(
      {static_cast<py::ssize_t>(r.final_positions.size()), py::ssize_t{2}});
  auto xy = positions.mutable_unchecked<2>();
  for (py::ssize_t i = 0; i < xy.shape(0); ++i) {
    xy(i, 0) = r.final_positions[static_cast<std::size_t>(i)].x;
    xy(i, 1) = r.final_positions[static_cast<std::size_t>(i)].y;
  }
  m.positions = positions;
  const auto vector_array = [](const std::vector<double>& v) {
    return py::array_t<double>(static_cast<py::ssize_t>(v.size()), v.data());
  };
  m.radii = vector_array(r.final_radii);
  m.psi6_modulus = vector_array(r.final_psi6_modulus);
  m.psi6_angle = vector_array(r.final_psi6_angle);
  return m;
}

py::object eos(const std::vector<py::object>& etas, const py::object& n,
               const py::object& equilibrate, const py::object& collisions, const py::object& seed,
               const py::object& blocks, const py::object& mix, const std::string& start,
               const py::object& threads, const py::object& seeds, const py::object& comm,
               const py::object& checkpoints) {
  const cli::GasOptionText text =
      option_text(n, py::float_(0.0), equilibrate, collisions, seed, blocks, mix, start);
  std::vector<cli::GasSpec> specs;
  std::uint64_t thread_count = 0;
  std::uint64_t seed_count = 1;
  try {
    for (const py::object& eta : etas) {
      specs.push_back(cli::parse_gas_spec(text, eta.cast<double>(), py::str(eta)));
    }
    thread_count = cli::parse_eos_threads(py::str(threads));
    seed_count = cli::parse_seed_count(py::str(seeds));
    specs = cli::seeded_specs(specs, seed_count);
  } catch (const cli::UsageError& error) {
    raise_usage(error);
  }
  std::string folder;
  if (!checkpoints.is_none()) {
    folder = py::str(py::module_::import("os").attr("fspath")(checkpoints));
    std::error_code error;
    std::filesystem::create_directories(folder, error);
    if (error) {
      throw py::value_error("checkpoints = " + folder + ": cannot create it: " + error.message());
    }
  }
  const cli::SingleProcessJob alone;
  std::optional<CommJob> shared;
  if (!comm.is_none()) shared.emplace(comm);
  const std::optional<std::vector<cli::GasOutcome>> ran = run_points(
      specs, thread_count, shared ? static_cast<const cli::EnsembleJob&>(*shared) : alone, folder);
  if (!ran) return py::none();  // another rank than 0 of comm: rank 0 has the results
  const std::vector<cli::GasOutcome>& outcomes = *ran;
  nlohmann::json points = nlohmann::json::array();
  for (std::size_t first = 0; first < specs.size(); first += seed_count) {
    if (seed_count == 1) {
      points.push_back(cli::gas_json(specs[first], outcomes[first]));
    } else {
      points.push_back(cli::seeded_point_json(
          std::span<const cli::GasSpec>(specs).subspan(first, seed_count),
          std::span<const cli::GasOutcome>(outcomes).subspan(first, seed_count)));
    }
  }
  return json_value(nlohmann::json{{"points", points}}.dump());
}

// Packings from consecutive seeds as `carom pack --seeds K --json` makes them (pack_ensemble.hpp),
// shared among comm's ranks (None at the others) and kept in `out`. Ctrl-C raises
// KeyboardInterrupt once every compression has stopped.
py::object pack_ensemble(const cli::PackOptions& o, std::uint64_t seeds, const py::object& comm,
                         const py::object& out) {
  (void)cli::parse_pack_options(o);
  const std::uint64_t threads = cli::parse_eos_threads(o.threads);
  std::string folder;
  if (!out.is_none()) {
    folder = py::str(py::module_::import("os").attr("fspath")(out));
    std::error_code error;
    std::filesystem::create_directories(std::filesystem::path(folder) / "runs", error);
    if (error) throw py::value_error("out = " + folder + ": cannot create it: " + error.message());
  }
  const cli::SingleProcessJob alone;
  std::optional<CommJob> shared;
  if (!comm.is_none()) shared.emplace(comm);
  CtrlCWatch ctrl_c;
  cli::PackEnsembleOutcome ensemble;
  {
    const py::gil_scoped_release unlocked;
    ensemble =
        cli::run_pack_ensemble(o, seeds, threads, folder, ctrl_c.stop(), ctrl_c.watch(),
                               shared ? static_cast<const cli::EnsembleJob&>(*shared) : alone);
  }
  ctrl_c.raise_if_signalled();
  warn_not_kept("a packing", ensemble.not_kept);
  if (!ensemble.leads) return py::none();
  for (const cli::PackRun& run : ensemble.runs) {
    if (!run.failure.empty()) {
      throw std::runtime_error("the packing of seed " + std::to_string(run.seed) +
                               " failed: " + run.failure);
    }
  }
  return json_value(cli::pack_ensemble_json(ensemble.runs).dump());
}

// A packing made as `carom pack --json` makes it. Ctrl-C stops it at the next window (the
// report then says end = "interrupted"). With seeds, comm or out: the ensemble's dict.
py::object pack(const py::object& n, const py::object& mix, const std::string& boundary,
                const py::object& aspect, const py::object& rate, const py::object& eta,
                const py::object& start_eta, const py::object& pressure_limit,
                const py::object& contact_tolerance, const py::object& seed,
                const py::object& seeds, const py::object& threads, const py::object& comm,
                const py::object& out) {
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
  o.seeds = py::str(seeds);
  o.threads = py::str(threads);
  std::string json;
  try {
    const std::uint64_t seed_count = cli::parse_seed_count(o.seeds);
    (void)cli::parse_eos_threads(o.threads);
    if (seed_count > 1 || !comm.is_none() || !out.is_none()) {
      return pack_ensemble(o, seed_count, comm, out);
    }
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
        py::arg("contact_tolerance") = py::none(), py::arg("seed") = 1, py::arg("seeds") = 1,
        py::arg("threads") = 2, py::arg("comm") = py::none(), py::arg("out") = py::none(),
        "A packing as `carom pack --json` makes it (eta None: until jammed): the same dict. "
        "seeds=K: K packings from seeds seed, seed + 1, ..., `threads` at once, as `carom pack "
        "--seeds K --json` reports them (the means, their _seed_err, each report in \"runs\"); "
        "comm (an mpi4py communicator): shared among its ranks, the dict at rank 0 and None at "
        "the others; out (a folder): each packing written there as it ends (seed-S.json) with "
        "its report (runs/), which a new start reads instead of compressing again");
  py::class_<GasMeasurement>(m, "GasMeasurement",
                             "What carom.gas reports (report, the same dict), with the "
                             "distributions as (x, y) arrays and the last configuration measured")
      .def_readonly("report", &GasMeasurement::report, "The dict carom.gas returns")
      .def_readonly("rdf", &GasMeasurement::rdf, "g(r): (r, g), r at the bins' centres")
      .def_readonly("speed", &GasMeasurement::speed, "(speed, probability density)")
      .def_readonly("psi6_local", &GasMeasurement::psi6_local,
                    "(|psi6_j|, probability density) of the local bond order")
      .def_readonly("msd", &GasMeasurement::msd, "(lag, mean-square displacement)")
      .def_readonly("positions", &GasMeasurement::positions,
                    "(N, 2) positions, wrapped into the cell, at the last structure sample")
      .def_readonly("radii", &GasMeasurement::radii, "(N,) radii")
      .def_readonly("psi6_modulus", &GasMeasurement::psi6_modulus, "(N,) |psi6_j|")
      .def_readonly("psi6_angle", &GasMeasurement::psi6_angle,
                    "(N,) arg psi6_j in (-pi, pi]; 0 where a disk has no neighbour");
  m.def("measure_gas", &measure_gas, py::kw_only(), py::arg("n") = 400, py::arg("eta") = 0.3,
        py::arg("equilibrate") = 50, py::arg("collisions") = 500, py::arg("seed") = 1,
        py::arg("blocks") = 16, py::arg("mix") = py::none(), py::arg("start") = "lattice",
        "carom.gas's run, with g(r), the speed, psi6 and MSD distributions as arrays");
  m.def("gas", &gas, py::arg("n") = 400, py::arg("eta") = 0.3, py::arg("equilibrate") = 50,
        py::arg("collisions") = 500, py::arg("seed") = 1, py::arg("blocks") = 16,
        py::arg("mix") = py::none(), py::arg("start") = "lattice",
        "A hard-disk gas measured as `carom gas --json` measures it: the same dict (NaN as None)");
  m.def("eos", &eos, py::arg("etas"), py::kw_only(), py::arg("n") = 400,
        py::arg("equilibrate") = 50, py::arg("collisions") = 500, py::arg("seed") = 1,
        py::arg("blocks") = 16, py::arg("mix") = py::none(), py::arg("start") = "lattice",
        py::arg("threads") = 2, py::arg("seeds") = 1, py::arg("comm") = py::none(),
        py::arg("checkpoints") = py::none(),
        "The equation of state at each packing fraction in etas, `threads` runs at once, as "
        "`carom eos --json`: {\"points\": [one gas() dict per point]}; with seeds=K each point "
        "is K runs (seeds seed, seed + 1, ...) and its dict gives the mean, the block-average "
        "error (_err) and the error between the seeds (_seed_err), each run's dict in \"runs\". "
        "comm (an mpi4py communicator): the runs shared among its ranks, the result at rank 0 "
        "(None at the others), the same bit for bit. checkpoints (a folder every rank sees): "
        "each run kept there as it ends, and one kept there before read instead of run again "
        "(the files of `carom eos --out DIR` in DIR/points)");
}

}  // namespace carom::python
