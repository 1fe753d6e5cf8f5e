// The data half of `tactile._core`: opening a database, listing runs, loading a run as numpy
// arrays (views into the loaded run, no copy where the run's columns allow), and reading and
// writing labels through the workspace calls the workbench makes.
#include <pybind11/stl.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <vector>

#include "python/src/common.h"
#include "storage/run_database.h"

namespace tactile::python {
namespace {

// A read-only numpy view of `count` elements (or a 2-D shape) owned by `owner`.
template <class T>
py::array view(const py::object& owner, const T* data, std::vector<py::ssize_t> shape,
               std::vector<py::ssize_t> strides) {
  py::array out(py::dtype::of<T>(), std::move(shape), std::move(strides), data, owner);
  py::detail::array_proxy(out.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
  return out;
}

template <class T>
py::array column(const py::object& owner, const std::vector<T>& values) {
  return view<T>(owner, values.data(), {static_cast<py::ssize_t>(values.size())},
                 {static_cast<py::ssize_t>(sizeof(T))});
}

// Columns side by side in a new steps x columns array (the run keeps them apart).
py::array_t<double> stacked(std::initializer_list<const std::vector<double>*> columns) {
  const auto steps = static_cast<py::ssize_t>((*columns.begin())->size());
  const auto width = static_cast<py::ssize_t>(columns.size());
  py::array_t<double> out({steps, width});
  double* o = out.mutable_data();
  std::size_t c = 0;
  for (const std::vector<double>* column : columns) {
    const double* in = column->data();
    for (py::ssize_t t = 0; t < steps; ++t)
      o[t * width + static_cast<py::ssize_t>(c)] = in[t];
    ++c;
  }
  return out;
}

// Strips "sqlite://" and "sqlite:" from a database address; a PostgreSQL address
// (postgresql://..., postgres://..., libpq's key=value form) is kept as it is.
std::string databasePath(const std::string& address) {
  if (storage::isServerAddress(address)) return address;
  for (const char* prefix : {"sqlite:///", "sqlite://", "sqlite:"}) {
    const std::string p(prefix);
    if (address.rfind(p, 0) == 0) {
      // sqlite:///abs/path keeps its leading slash.
      return p == "sqlite:///" ? "/" + address.substr(p.size()) : address.substr(p.size());
    }
  }
  if (address.find("://") != std::string::npos) {
    throw py::value_error("unsupported database address '" + storage::shownAddress(address) +
                          "': a file (a path or sqlite:///path) or a PostgreSQL server "
                          "(postgresql://...) can be opened");
  }
  return address;
}

std::shared_ptr<Database> openDatabase(const std::string& address, bool create, bool readOnly) {
  const std::string path = databasePath(address);
  storage::OpenOptions options;
  options.mode = readOnly ? storage::OpenMode::ReadOnly
                          : (create ? storage::OpenMode::Create : storage::OpenMode::ReadWrite);
  const bool server = storage::isServerAddress(path);
  if (!server && !create && path != ":memory:" && !std::filesystem::exists(path)) {
    raiseOSError(ENOENT, "no database at this path (open(path, create=True) makes one)", path);
  }
  Result<std::unique_ptr<workspace::Workspace>> ws = [&] {
    py::gil_scoped_release release;
    return workspace::Workspace::open(path, options);
  }();
  // A server address is shown without its password (in errors and the repr).
  const std::string shown = storage::shownAddress(path);
  if (!ws) raiseOSError(EIO, ws.error().message, ws.error().file.empty() ? shown : ws.error().file);
  auto db = std::make_shared<Database>();
  db->path = shown;
  db->workspace = std::move(ws.value());
  return db;
}

py::dict runInfoDict(const storage::RunInfo& r) {
  py::dict d;
  d["name"] = r.name;
  d["scene"] = r.scene;
  d["steps"] = r.stepCount;
  d["subject"] = r.subject;
  d["outcome"] = r.outcome;
  d["dt"] = r.dtSeconds ? py::object(py::float_(*r.dtSeconds)) : py::object(py::none());
  d["has_truth"] = r.hasTruth;
  d["source_file"] = r.sourceFile;
  d["imported_at"] = r.importedAt;
  d["id"] = r.id;
  return d;
}

std::int64_t labelSetId(Database& db, const std::string& set) {
  auto info = db.ws().labelStore().find(set);
  if (!info) raiseValueError(info.error());
  return info->id;
}

py::dict labelsOf(Database& db, const std::string& set, const std::string& runName) {
  workspace::Workspace& rws = db.ws();
  auto run = rws.runStore().find(runName);
  if (!run) raiseValueError(run.error());
  const std::int64_t setId = labelSetId(db, set);
  auto segments = rws.labelStore().segments(setId, run->id);
  if (!segments) raiseValueError(segments.error());
  const auto steps = static_cast<py::ssize_t>(run->stepCount);
  py::dict classes;
  std::vector<py::array_t<std::int8_t>> arrays;
  for (const GroupInfo& g : kSensorGroups) {
    py::array_t<std::int8_t> a(steps);
    std::fill(a.mutable_data(), a.mutable_data() + steps, std::int8_t{-1});
    arrays.push_back(a);
    classes[py::str(std::string(g.shortName))] = a;
  }
  py::list list;
  for (const storage::LabelSegment& s : segments.value()) {
    std::int8_t* out = arrays[static_cast<std::size_t>(groupIndex(s.group))].mutable_data();
    for (std::int64_t t = s.firstStep; t <= s.lastStep && t < steps; ++t)
      out[t] = static_cast<std::int8_t>(s.cls);
    py::dict d;
    d["id"] = s.id;
    d["group"] = std::string(groupInfo(s.group).shortName);
    d["first_step"] = s.firstStep;
    d["last_step"] = s.lastStep;
    d["class"] = std::string(contactClassName(s.cls));
    d["annotator"] = s.annotator;
    list.append(d);
  }
  py::dict out;
  out["classes"] = classes;
  out["segments"] = list;
  return out;
}

// Adds segments (group, first_step, last_step, class) to the set, creating it when absent, each
// through Workspace::addSegment (one committed transaction each, newest wins), as the workbench's
// label edits do. Returns the new segments' ids.
std::vector<std::int64_t> addSegments(Database& db, const std::string& set,
                                      const std::string& runName, const py::list& segments,
                                      const std::optional<std::string>& annotator) {
  workspace::Workspace& rws = db.ws();
  std::vector<storage::LabelSegment> toAdd;
  for (const py::handle item : segments) {
    const auto t = item.cast<py::tuple>();
    if (t.size() != 4) throw py::value_error("a segment is (group, first_step, last_step, class)");
    storage::LabelSegment s;
    s.run = runName;
    s.group = parseGroup(t[0].cast<std::string>());
    s.firstStep = t[1].cast<std::int64_t>();
    s.lastStep = t[2].cast<std::int64_t>();
    const py::handle cls = t[3];
    if (py::isinstance<py::str>(cls)) {
      const auto c = parseContactClass(cls.cast<std::string>());
      if (!c) {
        throw py::value_error("unknown class '" + cls.cast<std::string>() +
                              "' (NoContact, Wall, Corner, LeavingWall, DeadPath)");
      }
      s.cls = *c;
    } else {
      const int code = cls.cast<int>();
      if (code < 0 || code >= kContactClassCount) {
        throw py::value_error("class code " + std::to_string(code) + " is not 0-4");
      }
      s.cls = static_cast<ContactClass>(code);
    }
    toAdd.push_back(std::move(s));
  }
  auto found = rws.labelStore().find(set);
  std::int64_t setId = 0;
  std::string setAnnotator;
  if (found) {
    setId = found->id;
    setAnnotator = found->annotator;
  } else {
    auto created = rws.labelStore().create(set, annotator.value_or(""));
    if (!created) raiseValueError(created.error());
    setId = created.value();
    setAnnotator = annotator.value_or("");
  }
  std::vector<std::int64_t> ids;
  for (storage::LabelSegment& s : toAdd) {
    s.annotator = annotator.value_or(setAnnotator);
    auto edit = db.ws().addSegment(setId, s);
    if (!edit) raiseValueError(edit.error());
    ids.push_back(edit->segmentId);
  }
  return ids;
}

}  // namespace

void bindData(py::module_& m) {
  py::class_<Run, std::shared_ptr<Run>>(m, "Run",
                                        "A run loaded from a database; its arrays are read-only "
                                        "views that keep the run alive.")
      .def_readonly("name", &Run::name)
      .def_property_readonly(
          "steps", [](const Run& r) { return static_cast<py::ssize_t>(r.data.stepCount()); })
      .def_property_readonly(
          "sensors",
          [](py::object self) {
            const Run& r = self.cast<const Run&>();
            return view<double>(self, r.data.sensors.data(),
                                {static_cast<py::ssize_t>(r.data.stepCount()), kValuesPerStep},
                                {kValuesPerStep * 8, 8});
          },
          "steps x 88: n0, s0, n1, s1, ..., n43, s43 (as stored)")
      .def_property_readonly(
          "normal",
          [](py::object self) {
            const Run& r = self.cast<const Run&>();
            return view<double>(self, r.data.sensors.data(),
                                {static_cast<py::ssize_t>(r.data.stepCount()), kSensorCount},
                                {kValuesPerStep * 8, 16});
          },
          "steps x 44 normal values (a view)")
      .def_property_readonly(
          "shear",
          [](py::object self) {
            const Run& r = self.cast<const Run&>();
            return view<double>(self, r.data.sensors.data() + 1,
                                {static_cast<py::ssize_t>(r.data.stepCount()), kSensorCount},
                                {kValuesPerStep * 8, 16});
          },
          "steps x 44 shear values (a view)")
      .def_property_readonly(
          "pose",
          [](const Run& r) {
            return stacked({&r.data.x, &r.data.y, &r.data.theta});
          },
          "steps x 3: x, y, theta (a new array)")
      .def_property_readonly(
          "command",
          [](const Run& r) {
            return stacked({&r.data.v, &r.data.omega});
          },
          "steps x 2: v, omega (a new array)")
      .def_property_readonly(
          "x", [](py::object self) { return column(self, self.cast<const Run&>().data.x); })
      .def_property_readonly(
          "y", [](py::object self) { return column(self, self.cast<const Run&>().data.y); })
      .def_property_readonly(
          "theta", [](py::object self) { return column(self, self.cast<const Run&>().data.theta); })
      .def_property_readonly(
          "v", [](py::object self) { return column(self, self.cast<const Run&>().data.v); })
      .def_property_readonly(
          "omega", [](py::object self) { return column(self, self.cast<const Run&>().data.omega); })
      .def_property_readonly(
          "blocked",
          [](py::object self) {
            const Run& r = self.cast<const Run&>();
            const std::vector<std::uint8_t>& b = r.data.blocked;
            py::array out(py::dtype("bool"), {static_cast<py::ssize_t>(b.size())}, {1}, b.data(),
                          self);
            py::detail::array_proxy(out.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
            return out;
          },
          "steps booleans: the robot was blocked (a view)")
      .def_property_readonly(
          "truth",
          [](py::object self) -> py::object {
            const Run& r = self.cast<const Run&>();
            if (!r.data.hasTruth()) return py::none();
            static_assert(sizeof(ContactClass) == 1);
            return view<std::uint8_t>(
                self, reinterpret_cast<const std::uint8_t*>(r.data.truth.data()),
                {static_cast<py::ssize_t>(r.data.stepCount()), kGroupCount}, {kGroupCount, 1});
          },
          "steps x 8 class codes (tactile.CLASSES) in group order (tactile.GROUPS), or None")
      .def_property_readonly(
          "dt",
          [](const Run& r) -> py::object {
            const auto dt = r.data.dtSeconds();
            return dt ? py::object(py::float_(*dt)) : py::object(py::none());
          },
          "seconds per step, or None")
      .def_property_readonly(
          "metadata",
          [](const Run& r) {
            py::dict d;
            for (const auto& [key, value] : r.data.metadata)
              d[py::str(key)] = value;
            return d;
          },
          "the run's metadata lines as a dict")
      .def("__repr__", [](const Run& r) {
        return "<tactile.Run '" + r.name + "', " + std::to_string(r.data.stepCount()) + " steps>";
      });

  py::class_<Database, std::shared_ptr<Database>>(m, "Database")
      .def_readonly("path", &Database::path)
      .def("runs",
           [](Database& db) {
             auto catalog = db.ws().runs();
             if (!catalog) raiseFileError(catalog.error(), db.path);
             py::list out;
             for (const storage::RunCatalogEntry& e : catalog.value()) {
               py::dict d = runInfoDict(e.run);
               d["label_sets"] = e.labelSets;
               out.append(d);
             }
             return out;
           })
      .def(
          "run",
          [](Database& db, const std::string& name) {
            auto run = std::make_shared<Run>();
            run->name = name;
            Result<RunData> loaded = [&] {
              py::gil_scoped_release release;
              return db.ws().loadRun(name);
            }();
            if (!loaded) raiseValueError(loaded.error());
            run->data = std::move(loaded.value());
            return run;
          },
          py::arg("name"))
      .def("label_sets",
           [](Database& db) {
             auto sets = db.ws().labelSets();
             if (!sets) raiseFileError(sets.error(), db.path);
             py::list out;
             for (const storage::LabelSetCatalogEntry& e : sets.value()) {
               py::dict d;
               d["name"] = e.set.name;
               d["annotator"] = e.set.annotator;
               d["segments"] = e.set.segmentCount;
               d["created_at"] = e.set.createdAt;
               d["runs"] = e.runs;
               out.append(d);
             }
             return out;
           })
      .def("labels", &labelsOf, py::arg("set"), py::arg("run"))
      .def("add_segments", &addSegments, py::arg("set"), py::arg("run"), py::arg("segments"),
           py::arg("annotator") = py::none())
      .def("models",
           [](Database& db) {
             auto models = db.ws().models();
             if (!models) raiseFileError(models.error(), db.path);
             py::list out;
             for (const storage::ModelInfo& i : models.value()) {
               py::dict d;
               d["name"] = i.name;
               d["id"] = i.id;
               d["created_at"] = i.createdAt;
               d["trained_on"] = i.trainedOnJson;
               d["metrics"] = i.metricsJson;
               out.append(d);
             }
             return out;
           })
      .def("sweeps",
           [](Database& db) {
             auto sweeps = db.ws().sweeps();
             if (!sweeps) raiseFileError(sweeps.error(), db.path);
             py::list out;
             for (const storage::SweepInfo& i : sweeps.value()) {
               py::dict d;
               d["id"] = i.id;
               d["name"] = i.name;
               d["created_at"] = i.createdAt;
               d["cells"] = i.cellCount;
               d["configuration"] = i.configurationJson;
               out.append(d);
             }
             return out;
           })
      .def("close", [](Database& db) { db.workspace.reset(); })
      .def("__repr__", [](const Database& db) { return "<tactile.Database " + db.path + ">"; });

  m.def("open", &openDatabase, py::arg("path"), py::arg("create") = false,
        py::arg("read_only") = false,
        "Opens a run database (a path or sqlite:///path). A missing file is an OSError unless "
        "create=True.");
}

}  // namespace tactile::python
