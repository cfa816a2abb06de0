// Parametric sweeps and the datasets they make: load_spec, run_sweep, read_results, dataset_box.
// SPDX-License-Identifier: BSD-3-Clause
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <atomic>
#include <chrono>
#include <exception>
#include <future>
#include <thread>

#include "bindings.hpp"
#include "corlab/core/error.hpp"
#include "corlab/dataset/impact_box.hpp"
#include "corlab/study/results_table.hpp"
#include "corlab/study/sweep.hpp"
#include "corlab/study/sweep_spec.hpp"

namespace py = pybind11;

namespace corlab::python {
namespace {

py::dict settings_dict(const study::Settings& settings) {
  py::dict d;
  for (const auto& [k, v] : settings) d[py::str(k)] = v;
  return d;
}

py::dict spec_dict(const study::SweepSpec& spec) {
  py::dict d;
  d["name"] = spec.name;
  d["description"] = spec.description;
  d["base"] = settings_dict(spec.base);
  py::dict grid;
  for (const auto& [k, values] : spec.grid) grid[py::str(k)] = values;
  d["grid"] = grid;
  py::list cases;
  for (const auto& c : spec.cases) cases.append(settings_dict(c));
  d["cases"] = cases;
  d["swept_keys"] = spec.swept_keys();
  py::list runs;
  for (const auto& run : spec.expand()) {
    py::dict r;
    r["id"] = run.id;
    r["settings"] = settings_dict(run.settings);
    runs.append(r);
  }
  d["runs"] = runs;
  return d;
}

py::list range_list(const dataset::Range& r) {
  py::list l;
  l.append(r.min);
  l.append(r.max);
  return l;
}

// The ranges of a dataset's design box (impact_box.hpp), each [min, max] [-].
py::dict box_dict(const dataset::ImpactBox& box) {
  py::dict d;
  d["k2"] = range_list(box.k2);
  d["modulus_ratio"] = range_list(box.modulus_ratio);
  d["sphere_yield_ratio"] = range_list(box.sphere_yield_ratio);
  d["nu"] = range_list(box.nu);
  d["hardening_ratio"] = range_list(box.hardening_ratio);
  d["density_ratio"] = range_list(box.density_ratio);
  d["radius_ratio"] = range_list(box.radius_ratio);
  d["flat_fraction"] = box.flat_fraction;
  d["velocity_ratio_min"] = box.velocity_ratio_min;
  d["damage_number_max"] = box.damage_number_max;
  return d;
}

py::dict summary_dict(const study::SweepSummary& s) {
  py::dict d;
  d["total"] = s.total;
  d["already_done"] = s.already_done;
  d["ran"] = s.ran;
  d["failed"] = s.failed;
  d["not_separated"] = s.not_separated;
  d["remaining"] = s.remaining();
  d["wall_s"] = s.wall_s;
  d["interrupted"] = s.interrupted;
  d["workers"] = s.workers;
  d["ranks"] = s.ranks;
  return d;
}

// corlab.dataset_box(name): the design box of a shipped dataset.
void def_dataset_box(py::module_& m) {
  m.def(
      "dataset_box",
      [](const std::string& name) -> py::dict {
        if (name == "flat") return box_dict(dataset::ImpactBox{});
        if (name == "pairs") return box_dict(dataset::pair_box());
        throw_invalid("name", name, "flat or pairs (the dataset's design box)");
      },
      py::arg("name"),
      "The design box of corlab's FE dataset `name` (flat: data/fe_restitution, pairs: "
      "data/fe_restitution_pairs), each input's [min, max] [-] (docs/theory/dataset.md): k2, "
      "modulus_ratio, sphere_yield_ratio, nu, hardening_ratio, density_ratio, radius_ratio (of "
      "the second spheres), and flat_fraction, velocity_ratio_min, damage_number_max.");
}

}  // namespace

void bind_study(py::module_& m) {
  def_dataset_box(m);
  m.def(
      "load_spec", [](const std::string& path) { return spec_dict(study::load_sweep_spec(path)); },
      py::arg("path"),
      "Parse and validate a sweep spec (TOML). Returns a dict: name, description, base, grid, "
      "cases, swept_keys and runs (each {'id', 'settings'}). Bad spec -> ValueError.");

  m.def(
      "run_sweep",
      [](const std::string& spec_path, const std::string& out_dir, int jobs, bool progress) {
        const study::SweepSpec spec = study::load_sweep_spec(spec_path);
        std::atomic<bool> cancel{false};
        study::SweepOptions options;
        options.jobs = jobs;
        options.progress = progress;
        options.cancel = &cancel;
        // Run without the GIL in a thread; this thread checks for Ctrl-C now and then, so a
        // KeyboardInterrupt cancels the sweep (finished rows are kept) instead of being ignored.
        if (study::launched_world_size() > 1) {
          // Under mpirun every MPI call must come from this thread (MPI_THREAD_FUNNELED).
          study::SweepSummary summary;
          {
            py::gil_scoped_release release;
            summary = study::run_sweep(spec, out_dir, options);
          }
          return summary_dict(summary);
        }
        std::future<study::SweepSummary> done;
        {
          py::gil_scoped_release release;
          done = std::async(std::launch::async,
                            [&] { return study::run_sweep(spec, out_dir, options); });
          while (done.wait_for(std::chrono::milliseconds(100)) != std::future_status::ready) {
            py::gil_scoped_acquire acquire;
            if (PyErr_CheckSignals() != 0) {
              cancel.store(true);
              PyErr_Clear();
            }
          }
        }
        const study::SweepSummary summary = done.get();
        if (cancel.load()) {
          PyErr_SetNone(PyExc_KeyboardInterrupt);
          throw py::error_already_set();
        }
        return summary_dict(summary);
      },
      py::arg("spec_path"), py::arg("out_dir"), py::arg("jobs") = 0, py::arg("progress") = false,
      "Run every case of the spec with the impact solver into out_dir/results.csv (resumes a "
      "previous run). jobs = cases at a time (0 = all cores). Returns the summary as a dict.");

  m.def(
      "read_results",
      [](const std::string& path) {
        const study::ResultsTable table = study::read_results(path);
        for (const auto& note : table.notes()) {
          py::module_::import("warnings").attr("warn")(note);
        }
        py::dict d;
        for (const auto& column : table.columns()) {
          if (table.is_numeric(column)) {
            const std::vector<double> values = table.numbers(column);
            d[py::str(column)] =
                py::array_t<double>(static_cast<py::ssize_t>(values.size()), values.data());
          } else {
            d[py::str(column)] = table.text(column);
          }
        }
        return d;
      },
      py::arg("path"),
      "Read a results.csv: dict column -> numpy array (numeric columns) or list of str. A cut "
      "last line of a sweep's results.csv or a repeated row is dropped with a UserWarning; a cut "
      "line elsewhere, a case_id with two different rows or a repeated column is a ValueError.");
}

}  // namespace corlab::python
