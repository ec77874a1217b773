#pragma once
// Shared by the esi-net tests: the library index over the corpus (built once per test run, no
// cache), building a network from YAML text, and the corpus paths.

#include <filesystem>
#include <string>
#include <vector>

#include "esi/net/library_index.hpp"
#include "esi/net/network.hpp"

namespace esi::test {

std::filesystem::path corpus_dir();
// corpus/esi, corpus/eni/esi and corpus/master-configs/lcec/esi.
const esi::net::LibraryIndex& corpus_index();
// Reads `yaml` as NETWORK.yaml (named `name`) and builds it against the corpus index; the
// file's own `esi:` is not looked at. Read errors are returned as build diagnostics.
esi::net::BuildResult build_corpus_network(const std::string& yaml, const std::string& name = "network.yaml");
// CherryECAT's ECAT_CIA402 ESI (corpus/eni/esi), which the corpus networks pick by `esi_file:`.
std::string cherry_esi_file();
// The declarations of IgH's application interface that the generated igh_config.c uses,
// written for the tests from IgH's documentation (tests/net/data/igh_api/ecrt.h).
std::filesystem::path igh_api_dir();
// All diagnostics as text, for failure messages.
std::string diagnostics_text(const esi::Diagnostics& diagnostics);

}  // namespace esi::test

namespace esi::test {

// Networks over the corpus that the ENI tests run through the schema, both third-party readers
// and the determinism check: the four exports' topologies and networks that exercise start-up
// SDOs, configured PDO entries, complete access and identities above 0x7FFFFFFF.
struct NamedNetwork {
    std::string name;
    std::string yaml;
};
const std::vector<NamedNetwork>& corpus_networks();

}  // namespace esi::test
