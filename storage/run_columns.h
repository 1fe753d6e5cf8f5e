// Internal: a whole run's steps read straight into columns laid out by the caller
// (docs/storage.md#reading); RunDatabase::loadRun is this into RunData's columns. One pass over the
// steps rows with one reused statement, each row checked against its checksum and its sensors blob
// decoded in place, with no allocation per step. A long run of an SQLite file is read on two
// threads, each with its own connection stepping ranges of the steps; elsewhere (a server, a
// database in memory) its rows are checked and decoded on a second thread while this one walks
// them.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "run/contact_class.h"
#include "storage/run_database.h"

namespace tactile::storage {

// What a run is before its steps are read: the caller sizes its columns from it.
struct RunShape {
  std::string name;
  std::int64_t steps = 0;
  bool hasTruth = false;
  std::vector<std::pair<std::string, std::string>> metadata;
  std::vector<std::string> extraColumns;  // x_ column names
  std::int64_t checksum = 0;              // the run row's stored checksum
};

// One value per step: step t's value goes to data[t * stride].
template <class T>
struct StridedColumn {
  T* data = nullptr;
  std::ptrdiff_t stride = 1;
};

// Where each step's values go. Every target has room for all the run's steps.
struct RunColumns {
  // Sensor i's normal value of step t goes to normal[t * stepStride + i * sensorStride], its shear
  // value to shear[t * stepStride + i * sensorStride]. RunData::sensors is normal = sensors,
  // shear = sensors + 1, stepStride 88, sensorStride 2; two steps x 44 arrays are stepStride 44,
  // sensorStride 1.
  double* normal = nullptr;
  double* shear = nullptr;
  std::ptrdiff_t stepStride = 0;
  std::ptrdiff_t sensorStride = 0;
  // True when every sensor target already holds +0.0 (a vector just resized, calloc'd memory):
  // a sparse blob then writes only its non-zero values.
  bool sensorsZeroed = false;
  StridedColumn<double> x, y, theta, v, omega;
  StridedColumn<std::uint8_t> blocked;
  // steps x kGroupCount classes (row-major), when the run has truth; may be null otherwise.
  ContactClass* truth = nullptr;
  // The x_ values (steps x extraColumns, row-major) are appended here when not null.
  std::vector<std::string>* extraValues = nullptr;
};

// Reads run `runId` whole: `layout` is called once with the run's shape, before any step is read,
// and says where every step's values go. Throws db::DbError with loadWindow's messages for the
// same damage (a checksum that does not match, a missing step, a malformed blob).
void readRunColumns(RunDatabase::Impl& impl, std::int64_t runId,
                    const std::function<RunColumns(const RunShape&)>& layout);

}  // namespace tactile::storage
