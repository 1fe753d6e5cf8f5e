// The Python module `tactile._core` (docs/python.md): the product's own storage, feature and
// learning calls, the same ones the CLI and the workbench make. The package `tactile` around it
// (python/tactile/) adds pandas tables and the scikit-learn estimators.
#include <atomic>
#include <cerrno>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <thread>

#include "python/src/common.h"

namespace tactile::python {

void raiseOSError(int errnoValue, const std::string& message, const std::string& path) {
  const py::tuple args = py::make_tuple(errnoValue, message, path);
  PyErr_SetObject(PyExc_OSError, args.ptr());
  throw py::error_already_set();
}

void raiseFileError(const Error& error, const std::string& path) {
  if (error.line > 0) throw py::value_error(error.text());
  const std::string file = error.file.empty() ? path : error.file;
  if (file.empty()) throw py::value_error(error.text());
  raiseOSError(EIO, error.message, file);
}

void raiseValueError(const Error& error) {
  throw py::value_error(error.text());
}

SensorGroup parseGroup(const std::string& name) {
  const auto group = parseSensorGroup(name);
  if (!group) {
    throw py::value_error("unknown group '" + name +
                          "' (expected F, FLC, L, RLC, B, RRC, R or FRC)");
  }
  return *group;
}

void runInterruptible(const std::function<void(const ProgressFn&)>& work) {
  std::atomic<bool> cancel{false};
  std::mutex mutex;
  std::condition_variable finished;
  bool done = false;
  bool interrupted = false;
  std::exception_ptr failure;
  const ProgressFn progress = [&cancel](std::size_t, std::size_t) { return !cancel.load(); };
  {
    py::gil_scoped_release release;
    std::thread worker([&] {
      try {
        work(progress);
      } catch (...) {
        failure = std::current_exception();
      }
      const std::lock_guard<std::mutex> lock(mutex);
      done = true;
      finished.notify_all();
    });
    std::unique_lock<std::mutex> lock(mutex);
    while (!done) {
      finished.wait_for(lock, std::chrono::milliseconds(50));
      if (done || interrupted) continue;
      lock.unlock();
      {
        py::gil_scoped_acquire acquire;
        // Runs Python's signal handlers; Ctrl+C leaves KeyboardInterrupt set on this thread.
        if (PyErr_CheckSignals() != 0) interrupted = true;
      }
      if (interrupted) cancel = true;
      lock.lock();
    }
    lock.unlock();
    worker.join();
  }
  if (interrupted) throw py::error_already_set();
  if (failure) std::rethrow_exception(failure);
}

void runInterruptibleHere(const std::function<void(const ProgressFn&)>& work) {
  std::atomic<bool> interrupted{false};
  const std::thread::id caller = std::this_thread::get_id();
  auto lastCheck = std::chrono::steady_clock::now();
  const ProgressFn progress = [&](std::size_t, std::size_t) {
    if (interrupted) return false;
    if (std::this_thread::get_id() != caller) return true;
    const auto now = std::chrono::steady_clock::now();
    if (now - lastCheck < std::chrono::milliseconds(50)) return true;
    lastCheck = now;
    const py::gil_scoped_acquire acquire;
    // Runs Python's signal handlers; Ctrl+C leaves KeyboardInterrupt set on this thread.
    if (PyErr_CheckSignals() != 0) interrupted = true;
    return !interrupted;
  };
  std::exception_ptr failure;
  {
    const py::gil_scoped_release release;
    try {
      work(progress);
    } catch (...) {
      failure = std::current_exception();
    }
  }
  if (interrupted) throw py::error_already_set();
  if (failure) std::rethrow_exception(failure);
}

}  // namespace tactile::python

PYBIND11_MODULE(_core, m) {
  m.doc() =
      "The Tactile Workbench core: run databases, features, classifiers, training and sweeps "
      "(docs/python.md).";
  m.attr("version") = std::string(tactile::workspace::programVersion());
  tactile::python::bindData(m);
  tactile::python::bindLearning(m);
}
