// Helper of the kill test: streams label edits into a database, one committed transaction each,
// and prints the number of every committed edit on stdout, until it is killed.
//   storage_kill_helper DB FIRST_EDIT
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <string>

#include "storage/run_database.h"

int main(int argc, char** argv) {
  using namespace tactile;
  using namespace tactile::storage;
  if (argc != 3) {
    std::fprintf(stderr, "usage: storage_kill_helper DB FIRST_EDIT\n");
    return 2;
  }
  auto db = RunDatabase::open(argv[1]);
  if (!db) {
    std::fprintf(stderr, "%s\n", db.errorText().c_str());
    return 1;
  }
  auto set = db.value()->labels().find("kill");
  if (!set) {
    std::fprintf(stderr, "%s\n", set.errorText().c_str());
    return 1;
  }
  auto run = db.value()->runs().find("victim");
  if (!run) return 1;
  for (long long edit = std::atoll(argv[2]);; ++edit) {
    // Edit n labels one step of one group; edits never overlap, so each adds exactly one segment.
    LabelSegment segment;
    segment.runId = run->id;
    segment.group = static_cast<SensorGroup>(edit % kGroupCount);
    segment.firstStep = edit / kGroupCount;
    segment.lastStep = segment.firstStep;
    segment.cls = static_cast<ContactClass>(edit % kContactClassCount);
    if (segment.lastStep >= run->stepCount) return 0;
    auto id = db.value()->labels().addSegment(set->id, segment);
    if (!id) {
      std::fprintf(stderr, "%s\n", id.errorText().c_str());
      return 1;
    }
    const std::string line = std::to_string(edit) + "\n";
    if (::write(STDOUT_FILENO, line.data(), line.size()) < 0) return 1;
  }
}
