// The Python module `frontpack` (pybind11): the command line's pipeline (cli/pack_api.hpp) with
// the packing held in memory and its arrays handed to numpy without copies.
//   import frontpack
//   p = frontpack.pack("scene.yaml", seed=3)      # or a dict with the scene file's schema
//   p.centers, p.radii                            # numpy views, read-only (n x D, n)
//   p.record["metrics"]["volume_fraction_container"], p.analysis["coordination"]
//   frontpack.validate(p)["ok"]; p.write("out.vtu")
// Errors are Python exceptions with the command line's messages: frontpack.SceneError (a
// ValueError) names the file, line and key of a bad scene.
#include <pybind11/functional.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cli/analyze_command.hpp"
#include "cli/pack_api.hpp"
#include "cli/packing_input.hpp"
#include "cli/study_command.hpp"
#include "core/io/analysis_json.hpp"
#include "core/io/atomic_file.hpp"
#include "core/io/container_vtu.hpp"
#include "core/io/output_format.hpp"
#include "core/io/output_paths.hpp"
#include "core/io/packing_writers.hpp"
#include "core/io/scene_error.hpp"
#include "core/io/scene_yaml.hpp"
#include "core/io/study_yaml.hpp"
#include "frontpack/version.hpp"
#include "shapes/io/shape_packing_writers.hpp"
#include "shapes/pose.hpp"
#include "shapes/shape_registry.hpp"

namespace py = pybind11;

namespace fp {
namespace {

/// A packing made by pack(): the particles (PackingInput, with the scene), the record and the
/// verdict, and for shapes the arrays the particles' poses are unpacked into once.
struct PyPacking {
  PackOutcome run;
  std::vector<double> positions, orientations, sizes;  ///< shapes: n x D, n x 4 (3D) or n (2D), n
  std::vector<std::int32_t> template_ids;

  const PackingInput& in() const { return run.packed; }
  std::size_t size() const {
    const PackingInput& p = in();
    if (p.shapes) return p.dimension == 2 ? p.shapes2.size() : p.shapes3.size();
    return p.dimension == 2 ? p.packing2.size() : p.packing3.size();
  }
};

template <int D>
void unpack_shapes(PyPacking& out, const ShapePacking<D>& P) {
  for (const Particle<D>& p : P.particles) {
    const Vec<D> x = P.origin + p.pose.position;
    out.positions.insert(out.positions.end(), x.data(), x.data() + D);
    const Eigen::Vector4d q = quaternion_of<D>(p.pose.rotation);
    if constexpr (D == 3) out.orientations.insert(out.orientations.end(), q.data(), q.data() + 4);
    else out.orientations.push_back(2 * std::atan2(q[3], q[0]));  // the rotation about z
    out.sizes.push_back(p.size);
    out.template_ids.push_back(p.template_id);
  }
}

/// A read-only numpy array over `data` (rows x cols, or rows when cols is 0) owned by `owner`.
template <class T>
py::array view(const T* data, std::size_t rows, std::size_t cols, std::size_t row_stride, py::handle owner) {
  std::vector<py::ssize_t> shape{static_cast<py::ssize_t>(rows)}, strides{static_cast<py::ssize_t>(row_stride)};
  if (cols > 0) shape.push_back(static_cast<py::ssize_t>(cols)), strides.push_back(sizeof(T));
  py::array a(py::dtype::of<T>(), shape, strides, data, owner);
  py::detail::array_proxy(a.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
  return a;
}

/// The centres in absolute coordinates: a view of the packing's own when its frame is at the
/// origin (a scene near the origin), else computed once (origin + local, rounded as the
/// writers' doubles are).
template <int D>
py::array centers_of(const Packing<D>& P, py::handle owner) {
  if (P.origin.isZero()) return view(P.centers.empty() ? nullptr : P.centers[0].data(), P.size(), D, sizeof(Vec<D>), owner);
  py::array_t<double> a({static_cast<py::ssize_t>(P.size()), static_cast<py::ssize_t>(D)});
  auto w = a.mutable_unchecked<2>();
  for (std::size_t i = 0; i < P.size(); ++i)
    for (int k = 0; k < D; ++k) w(static_cast<py::ssize_t>(i), k) = P.origin[k] + P.centers[i][k];
  return a;
}

py::object json_loads(const std::string& text) { return py::module_::import("json").attr("loads")(text); }

/// numpy's scalars and arrays as plain Python (json.dumps' `default`, for what it cannot write):
/// a scene dict built with numpy is the same scene.
py::object plain(const py::object& o) {
  const py::module_ sys = py::module_::import("sys");
  if (sys.attr("modules").contains("numpy")) {
    const py::module_ np = py::module_::import("numpy");
    if (py::isinstance(o, np.attr("generic")) || py::isinstance(o, np.attr("ndarray"))) return o.attr("tolist")();
  }
  throw py::type_error("a scene value is a number, text, flag, list or dict (or numpy's), not " +
                       py::str(py::type::of(o).attr("__name__")).cast<std::string>() + ": " + py::repr(o).cast<std::string>());
}

/// JSON text (a subset of YAML): one key per line for documents (messages name their lines),
/// on one line for a --set value.
std::string json_dumps(const py::object& o, bool lines = true) {
  const py::object dumps = py::module_::import("json").attr("dumps");
  const py::cpp_function to_plain(&plain);
  try {
    return (lines ? dumps(o, py::arg("indent") = 1, py::arg("default") = to_plain) : dumps(o, py::arg("default") = to_plain))
        .cast<std::string>();
  } catch (py::error_already_set& e) {
    if (!e.matches(PyExc_RecursionError)) throw;
    throw py::value_error("the scene is nested too deeply (or holds itself) to be read");
  }
}

/// `progress=`: None or something to call.
void check_callable(const py::object& f, const char* name, const char* signature) {
  if (!f.is_none() && !PyCallable_Check(f.ptr()))
    throw py::type_error(std::string(name) + " must be callable, " + name + signature + ", or None (got " +
                         py::str(py::type::of(f).attr("__name__")).cast<std::string>() + ")");
}

/// A path given as str or os.PathLike.
std::string path_of(const py::object& o) { return py::module_::import("os").attr("fspath")(o).cast<std::string>(); }

/// `set={"packer.front": "fifo", ...}` as --set changes (values as JSON, a subset of YAML).
std::vector<SceneOverride> overrides_from(const py::object& changes) {
  std::vector<SceneOverride> out;
  if (changes.is_none()) return out;
  for (const auto& [key, value] : changes.cast<py::dict>()) {
    const std::string k = py::str(key).cast<std::string>();
    const std::string v = py::isinstance<py::str>(value) ? value.cast<std::string>() : json_dumps(py::reinterpret_borrow<py::object>(value), false);
    SceneOverride o;
    o.key = k;
    o.value = v;
    o.origin.file = "set[" + k + "]";
    if (!is_scene_key(k)) throw SceneError(o.origin.file, 0, 0, k, std::string("not a scene key (") + kSceneKeyForm + ")");
    out.push_back(std::move(o));
  }
  return out;
}

/// The scene of `source`: a path (str or os.PathLike) to a scene file, or a dict with the scene
/// file's schema (given to the parser as JSON, a subset of YAML; messages name its dotted keys).
Scene scene_from(const py::object& source, const std::vector<SceneOverride>& changes = {}) {
  if (py::isinstance<py::dict>(source)) return parse_scene(json_dumps(source), "<dict>", changes);
  return load_scene(path_of(source), changes);
}

/// frontpack.IncompletePackingWarning (a UserWarning), made when the module is imported.
PyObject* incomplete_packing_warning = nullptr;

std::shared_ptr<PyPacking> pack(const py::object& source, std::optional<std::uint64_t> seed, std::optional<long long> threads,
                                py::object progress, const py::object& changes) {
  check_callable(progress, "progress", "(n, seconds, volume_fraction)");
  if (threads) check_threads(*threads, "threads");
  Scene scene = scene_from(source, overrides_from(changes));
  prepare_scene(scene, seed, threads ? std::optional<int>(static_cast<int>(*threads)) : std::nullopt);
  ProgressFn fn;
  if (!progress.is_none())
    fn = [&progress](std::uint64_t n, double seconds, double vf) {
      const py::gil_scoped_acquire gil;
      if (PyErr_CheckSignals() != 0) throw py::error_already_set();  // Ctrl-C stops the run
      progress(n, seconds, vf);                                       // an exception in it too
    };
  auto out = std::make_shared<PyPacking>();
  {
    const py::gil_scoped_release released;
    out->run = pack_scene(scene, fn);
  }
  const PackingInput& p = out->in();
  if (p.shapes) p.dimension == 2 ? unpack_shapes<2>(*out, p.shapes2) : unpack_shapes<3>(*out, p.shapes3);
  // Where the command exits 4: a warning (an error under `-W error`), the packing still returned.
  if (!out->run.incomplete.empty() &&
      PyErr_WarnEx(incomplete_packing_warning, ("the packing is incomplete: " + out->run.incomplete).c_str(), 1) != 0)
    throw py::error_already_set();
  return out;
}

/// f(the packing in its scene): the one it was packed in, or `scene` (a path or dict) given
/// instead (then on a copy of the particles in that scene's frame: packing_in_scene refuses
/// one they cannot be in), without the GIL. `tolerance` < 0: the scene's.
template <class F>
auto in_scene(const PyPacking& p, const py::object& scene, double tolerance, long long threads, F&& f) {
  if (std::isnan(tolerance) || std::isinf(tolerance))
    throw py::value_error("tolerance must be a finite number (< 0: the scene's), got " + std::to_string(tolerance));
  check_threads(threads, "threads");
  if (scene.is_none()) {
    const py::gil_scoped_release released;
    return f(p.in());
  }
  const PackingInput in = packing_in_scene(p.in(), scene_from(scene));
  const py::gil_scoped_release released;
  return f(in);
}

/// Writes the packing to `path`, checked as the command line checks its outputs first: no
/// output (nor a side file of one) may be a file the packing was made from (its scene, a mesh)
/// or another output.
void write_file(const PyPacking& p, const py::object& where, const std::string& format, const std::string& surfaces) {
  const std::string path = path_of(where);
  const OutputFormat f = format.empty() ? format_from_extension(path) : parse_output_format(format);
  const SurfaceDetail detail = parse_surface_detail(surfaces);
  const PackingInput& in = p.in();
  if (detail != SurfaceDetail::Fine && (!in.shapes || f != OutputFormat::Vtu))
    throw py::value_error("surfaces: the surfaces side file is written beside a vtu output of particles of shapes only");
  std::vector<NamedPath> writes{{path, "Packing.write", "output"}};
  if (in.shapes)  // shape packings write a side file for vtu and lammps
    for (const std::string& side : companion_paths(f, path, detail))
      writes.push_back({side, "Packing.write", "the side file of output '" + path + "'"});
  // Beside a vtu output, the container's boundary, when the scene it was packed in is known.
  const bool container_file = f == OutputFormat::Vtu && in.scene;
  if (container_file) writes.push_back({container_vtu_path(path), "Packing.write", "the side file of output '" + path + "'"});
  check_output_paths(writes, in.scene ? scene_reads(*in.scene, "the scene of frontpack.pack") : std::vector<NamedPath>{});
  const py::gil_scoped_release released;
  AtomicFileGroup all_or_nothing;
  if (in.shapes) {
    in.dimension == 2 ? write_packing<2>(f, path, in.shapes2, p.run.record, detail)
                      : write_packing<3>(f, path, in.shapes3, p.run.record, detail);
  } else {
    in.dimension == 2 ? write_packing<2>(f, path, in.packing2, p.run.record) : write_packing<3>(f, path, in.packing3, p.run.record);
  }
  if (container_file) {
    if (in.dimension == 2) write_container_vtu(container_vtu_path(path), *in.scene->container<2>());
    else write_container_vtu(container_vtu_path(path), *in.scene->container<3>());
  }
  all_or_nothing.commit();
}

/// A CSV cell as Python: a number, a flag, or the text.
py::object cell(const std::string& text) {
  if (text == "true" || text == "false") return py::bool_(text == "true");
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (!text.empty() && end == text.c_str() + text.size()) {
    if (text.find_first_of(".eEn") == std::string::npos && text.size() < 19) return py::int_(std::stoll(text));
    return py::float_(v);
  }
  return py::str(text);
}

py::dict row_dict(const StudyRow& row) {
  py::dict d;
  for (const auto& k : row.keys) d[py::str(k)] = cell(study_value(row, k));
  return d;
}

py::dict study(const py::object& source, long long jobs, bool plots, const py::object& progress, const py::object& executable) {
  check_callable(progress, "progress", "(done, total, row)");
  if (jobs < 0 || jobs > kMaxStudyJobs)
    throw py::value_error("jobs must be an integer from 0 (the study's) to " + std::to_string(kMaxStudyJobs) + " (got " +
                          std::to_string(jobs) + ")");
  StudySpec spec;
  if (py::isinstance<py::dict>(source)) {
    spec = parse_study(json_dumps(source), "<dict>");
  } else {
    spec = load_study(path_of(source));
  }
  StudyOptions o;
  o.executable = executable.is_none() ? std::string(FRONTPACK_EXECUTABLE) : path_of(executable);
  if (access(o.executable.c_str(), X_OK) != 0)
    throw std::runtime_error("the frontpack command " + o.executable + " is not there (build it, or give executable=)");
  o.jobs = static_cast<int>(jobs);
  o.plots = plots;
  o.quiet = true;
  o.poll = [] {
    const py::gil_scoped_acquire gil;
    if (PyErr_CheckSignals() != 0) throw py::error_already_set();  // Ctrl-C stops the study
  };
  if (!progress.is_none())
    o.on_run = [&progress](const StudyRun&, const StudyRow& row, std::size_t done, std::size_t total) {
      const py::gil_scoped_acquire gil;
      progress(done, total, row_dict(row));
    };
  StudyOutcome out;
  {
    const py::gil_scoped_release released;
    out = run_study(spec, o);
  }
  if (plots && !out.plots_problem.empty()) throw std::runtime_error("no figures: " + out.plots_problem);
  py::dict d;
  d["folder"] = spec.output_dir;
  d["csv"] = out.csv_path;
  d["full_csv"] = out.full_csv_path;
  d["figures"] = out.plots;
  d["runs"] = out.runs;
  d["kept"] = out.kept;
  d["ran"] = out.ran;
  d["invalid"] = out.invalid;
  d["incomplete"] = out.incomplete;
  d["failed"] = out.failed;
  py::list rows;
  for (const StudyRow& r : out.rows) rows.append(row_dict(r));
  d["rows"] = rows;
  return d;
}

}  // namespace
}  // namespace fp

PYBIND11_MODULE(frontpack, m) {
  using namespace fp;
  m.doc() = "frontpack: dense packings of spheres, disks and shapes by the advancing front (and the methods beside it)";
  m.attr("__version__") = kVersion;
  py::register_exception<SceneError>(m, "SceneError", PyExc_ValueError);
  // A file that must not be written (it is read, or written twice; no folder): nothing was.
  py::register_exception<OutputPathError>(m, "OutputPathError", PyExc_ValueError);
  // A valid packing that is not the packing of the container its scene asks for (the command's
  // exit 4): frontpack.pack returns it and warns.
  incomplete_packing_warning = PyErr_NewExceptionWithDoc(
      "frontpack.IncompletePackingWarning",
      "frontpack.pack made a valid packing that is not the one its scene asks for: its stop ended the front before it "
      "filled the container, a target was missed, or the packer placed nearly nothing (Packing.incomplete says why)",
      PyExc_UserWarning, nullptr);
  if (!incomplete_packing_warning) throw py::error_already_set();
  m.add_object("IncompletePackingWarning", py::reinterpret_borrow<py::object>(incomplete_packing_warning));

  py::class_<PyPacking, std::shared_ptr<PyPacking>>(m, "Packing", "A packing made by frontpack.pack, with its run record")
      .def_property_readonly("dimension", [](const PyPacking& p) { return p.in().dimension; })
      .def_property_readonly("shapes", [](const PyPacking& p) { return p.in().shapes; },
                             "True for particles of shapes (positions, orientations, ...), False for spheres or disks")
      .def("__len__", &PyPacking::size)
      .def_property_readonly(
          "centers",
          [](py::object self) {
            const PyPacking& p = self.cast<const PyPacking&>();
            if (p.in().shapes) throw py::attribute_error("a packing of shapes has positions, not centers");
            return p.in().dimension == 2 ? centers_of<2>(p.in().packing2, self) : centers_of<3>(p.in().packing3, self);
          },
          "sphere (disk) centres, absolute coordinates, n x D (read-only; a view when the frame is at the origin)")
      .def_property_readonly(
          "radii",
          [](py::object self) {
            const PyPacking& p = self.cast<const PyPacking&>();
            if (p.in().shapes) throw py::attribute_error("a packing of shapes has sizes, not radii");
            const std::vector<double>& r = p.in().dimension == 2 ? p.in().packing2.radii : p.in().packing3.radii;
            return view(r.data(), r.size(), 0, sizeof(double), self);
          },
          "sphere (disk) radii, n (read-only view)")
      .def_property_readonly("positions", [](py::object self) {
            const PyPacking& p = self.cast<const PyPacking&>();
            if (!p.in().shapes) throw py::attribute_error("a packing of spheres has centers, not positions");
            return view(p.positions.data(), p.size(), p.in().dimension, p.in().dimension * sizeof(double), self);
          }, "shape positions (reference points), absolute, n x D")
      .def_property_readonly("orientations", [](py::object self) {
            const PyPacking& p = self.cast<const PyPacking&>();
            if (!p.in().shapes) throw py::attribute_error("a packing of spheres has no orientations");
            const bool q = p.in().dimension == 3;
            return view(p.orientations.data(), p.size(), q ? 4 : 0, (q ? 4 : 1) * sizeof(double), self);
          }, "3D: unit quaternions (w, x, y, z), n x 4; 2D: angles in radians, n")
      .def_property_readonly("sizes", [](py::object self) {
            const PyPacking& p = self.cast<const PyPacking&>();
            if (!p.in().shapes) throw py::attribute_error("a packing of spheres has radii, not sizes");
            return view(p.sizes.data(), p.size(), 0, sizeof(double), self);
          }, "the size drawn for each shape (on its template's size_on dimension), n")
      .def_property_readonly("template_ids", [](py::object self) {
            const PyPacking& p = self.cast<const PyPacking&>();
            if (!p.in().shapes) throw py::attribute_error("a packing of spheres has no templates");
            return view(p.template_ids.data(), p.size(), 0, sizeof(std::int32_t), self);
          }, "each shape's particle template (index into template_names), n")
      .def_property_readonly("template_names", [](const PyPacking& p) {
            const PackingInput& in = p.in();
            return in.dimension == 2 ? in.shapes2.template_names : in.shapes3.template_names;
          })
      .def_property_readonly("record", [](const PyPacking& p) { return json_loads(run_record_json(p.run.record)); },
                             "the run record (as `frontpack pack --record` writes it), the analysis under 'analysis'")
      .def_property_readonly("analysis", [](const PyPacking& p) { return json_loads(p.run.record.analysis_json); },
                             "the full analysis of the packing in its scene (as `frontpack analyze --json` gives it)")
      .def_property_readonly("valid", [](const PyPacking& p) { return p.run.valid; },
                             "the independent validation passed, or failed only its radii test for want of room (drafts "
                             "that never fitted; the command line exits 4 then, 3 otherwise)")
      .def_property_readonly("validation", [](const PyPacking& p) { return p.run.validation; })
      .def_property_readonly("complete", [](const PyPacking& p) { return p.run.incomplete.empty(); },
                             "False when the packing is not the packing of the container its scene asks for (the "
                             "command line exits 4 when it is valid); Packing.incomplete says why")
      .def_property_readonly("incomplete", [](const PyPacking& p) { return p.run.incomplete; },
                             "why the packing is incomplete (the record's info.incomplete), '' when complete")
      .def_property_readonly("summary", [](const PyPacking& p) { return p.run.summary; },
                             "the analysis and packer lines of the command line's summary")
      .def_property_readonly("scene_path", [](const PyPacking& p) { return p.in().scene->source_path; })
      .def("write", &write_file, py::arg("path"), py::arg("format") = "", py::kw_only(), py::arg("surfaces") = "fine",
           "writes the packing (vtu, yade, lammps, csv, json; default: from the extension) with its side files "
           "(vtu: <stem>.container.vtu, the container's boundary, and for shapes <stem>.surfaces.vtu, its detail "
           "`surfaces`: fine | coarse | none; lammps of clusters: <stem>.multisphere.txt), all or nothing; refuses "
           "(OutputPathError, a ValueError) a path that is its scene or a file the scene reads")
      .def("__repr__", [](const PyPacking& p) {
        return "<frontpack.Packing: " + std::to_string(p.size()) + (p.in().shapes ? " shapes" : " spheres") + ", " +
               std::to_string(p.in().dimension) + "D, scene " + p.in().scene->source_path +
               (p.run.incomplete.empty() ? "" : ", incomplete") + ">";
      });

  m.def(
      "shape_families",
      [] {
        const ShapeFamilies& families = ShapeFamilies::builtin();
        py::dict out;
        for (const std::string& name : families.names()) {
          const ShapeFamilyInfo& info = families.info(name);
          py::list dims;
          for (const int d : {2, 3})
            if (families.in_dimension(name, d)) dims.append(d);
          py::dict parameters;
          for (const auto& [parameter, meaning] : info.parameters) parameters[py::str(parameter)] = meaning;
          py::dict family;
          family["dimensions"] = dims;
          family["summary"] = info.summary;
          family["parameters"] = parameters;
          family["size_on"] = info.size_on;
          out[py::str(name)] = family;
        }
        return out;
      },
      "The shape families a scene's `shape:` may name: {name: {'dimensions': [2, 3], 'summary': ..., 'parameters': "
      "{name: meaning}, 'size_on': [the dimensions a size may be drawn on]}} (README: Non-spherical particles).");
  m.def("pack", &pack, py::arg("scene"), py::kw_only(), py::arg("seed") = py::none(), py::arg("threads") = py::none(),
        py::arg("progress") = py::none(), py::arg("set") = py::none(),
        "Packs a scene (a path to a scene file, or a dict with its schema) as `frontpack pack` does, without writing "
        "its outputs. seed, threads: as --seed and -j; set: {dotted key: value} as --set KEY=VALUE. "
        "progress(n, seconds, volume_fraction) is called about every 0.5 s; an exception raised in it (or Ctrl-C) "
        "stops the run.");
  m.def("study", &study, py::arg("study"), py::kw_only(), py::arg("jobs") = 0, py::arg("plots") = true,
        py::arg("progress") = py::none(), py::arg("executable") = py::none(),
        "Runs a study as `frontpack study` does (a path to a study file, or a dict with its schema; a dict's relative "
        "paths start at the working directory): every run in its own frontpack process, `jobs` at once (0: the "
        "study's), done runs kept. Returns {'folder', 'csv' (the main figures), 'full_csv' (every figure), 'figures', 'runs', 'kept', 'ran', 'invalid', 'incomplete', 'failed', "
        "'rows'}: rows are the full CSV's, as dicts of numbers, flags and text. progress(done, total, row) after each run; "
        "an exception in it (or Ctrl-C) stops the study (its runs are killed). executable: the frontpack command "
        "(default: the one built with this module).");
  m.def(
      "analyze",
      [](const PyPacking& p, const py::object& scene, double tolerance, long long threads, const py::object& plots) {
        const std::string folder = plots.is_none() ? std::string() : path_of(plots);  // with the GIL held
        return json_loads(in_scene(p, scene, tolerance, threads, [&](const PackingInput& in) {
          const PackingAnalysis a = analyze_input(in, tolerance, static_cast<int>(threads));
          if (!folder.empty()) {
            const std::string problem = draw_analysis_figures(in, a, folder);
            if (!problem.empty()) throw std::runtime_error("no figures: " + problem);
          }
          return analysis_json(a);
        }));
      },
      py::arg("packing"), py::kw_only(), py::arg("scene") = py::none(), py::arg("tolerance") = -1.0, py::arg("threads") = 0,
      py::arg("plots") = py::none(),
      "The analysis of `frontpack analyze PACKING --scene S --json`, as a dict: in the packing's scene, or `scene`. "
      "plots: an existing folder to draw the figures of `--plots` into (sections through the packing, profiles, "
      "statistics; Debian's python3-matplotlib).");
  m.def(
      "validate",
      [](const PyPacking& p, const py::object& scene, double tolerance, long long threads) {
        const ValidationReport r = in_scene(p, scene, tolerance, threads, [&](const PackingInput& in) {
          return validate_input(in, tolerance, -1.0, static_cast<int>(threads));
        });
        py::dict d = json_loads(validation_json_text(r));
        d["line"] = r.one_line();
        d["summary"] = r.summary();
        return d;
      },
      py::arg("packing"), py::kw_only(), py::arg("scene") = py::none(), py::arg("tolerance") = -1.0, py::arg("threads") = 0,
      "The verdict of `frontpack validate PACKING --scene S`, as a dict: the keys of the analysis' 'validation' "
      "(ok, overlap_count, outside_count, contacts, max_overlap_rel, ...), its one line and its summary.");
}
