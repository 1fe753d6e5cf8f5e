// Shared pieces of the Python module `tactile._core`: error translation, long calls that release
// the GIL and stop on Ctrl+C, and the objects shared by the data and learning halves.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <exception>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "analysis/model_file.h"
#include "base/error.h"
#include "base/progress.h"
#include "run/run.h"
#include "run/sensor_layout.h"
#include "workspace/workspace.h"

namespace tactile::python {

namespace py = pybind11;

// Raises OSError(errno, message, path): FileNotFoundError for ENOENT, as Python's own file calls.
[[noreturn]] void raiseOSError(int errnoValue, const std::string& message, const std::string& path);
// An Error from a file or database call: ValueError naming file and line when the error has a
// line (bad data), otherwise OSError with the path when it names a file, else ValueError.
[[noreturn]] void raiseFileError(const Error& error, const std::string& path);
// An Error about what was asked (unknown run, bad settings): ValueError with the error's text.
[[noreturn]] void raiseValueError(const Error& error);

// A group by short or long name ("R", "right side"); ValueError otherwise.
SensorGroup parseGroup(const std::string& name);

// Runs `work(progress)` with the GIL released on a worker thread while the calling thread waits
// and, every 50 ms, takes the GIL briefly to let Python handle signals (PyErr_CheckSignals). On
// Ctrl+C the progress callback handed to the core returns false, the core stops at its next
// check, and KeyboardInterrupt (or whatever the signal handler raised) is raised here. A C++
// exception in `work` is rethrown here.
void runInterruptible(const std::function<void(const ProgressFn&)>& work);

// The same for work that calls `progress` on the calling thread often (a one-thread fit, after
// every EM iteration): `work` runs here with the GIL released, no thread is started, and the
// progress callback itself takes the GIL to let Python handle signals, at most every 50 ms and
// only when called on this thread. Handing work to a thread and back costs a few milliseconds
// on a loaded machine (each thread waits its turn for a core).
void runInterruptibleHere(const std::function<void(const ProgressFn&)>& work);

// An open database: one Workspace (one connection), used from one thread at a time. Python holds
// the GIL around every call except the long ones, which hold `busy` instead.
struct Database {
  std::string path;
  std::unique_ptr<workspace::Workspace> workspace;
  workspace::Workspace& ws() {
    if (!workspace) throw py::value_error("the database " + path + " is closed");
    return *workspace;
  }
};

// A run loaded into memory; numpy arrays are views into it and keep it alive.
struct Run {
  std::string name;
  RunData data;
};

// A model bundle (one model per group).
struct Model {
  std::string name;  // the stored name, empty for a file
  analysis::ModelBundle bundle;
};

void bindData(py::module_& m);
void bindLearning(py::module_& m);

}  // namespace tactile::python
