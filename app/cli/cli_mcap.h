// MCAP on the command line (cli_mcap.cpp): `tactile mcap info`, and the MCAP forms of `import`
// and `export-run`, which cli_storage.cpp hands over to.
#pragma once

#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace tactile::cli {

// `mcap info` and `bench mcap`.
void registerMcapVerbs(CLI::App& app, CLI::App& bench);

// `tactile import --db DB FILE.mcap [--mapping MAP.json] [--name N] [--json]`.
int runMcapImport(const std::string& db, const std::vector<std::string>& files,
                  const std::string& mapping, const std::string& name, bool json);

// `tactile export-run --db DB --run R --format mcap --out R.mcap [--sets S...] [--model M]`.
int runMcapExport(const std::string& db, const std::string& run, const std::string& out,
                  const std::vector<std::string>& sets, const std::string& model, bool json);

// True when the path names an MCAP file by its extension (.mcap, any case).
bool isMcapPath(const std::string& path);

}  // namespace tactile::cli
