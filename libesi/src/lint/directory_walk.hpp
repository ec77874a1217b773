#pragma once
// The ESI files under a directory given to esi-lint. The walk must not let CI pass silently:
// a subdirectory that cannot be read is an error (not skipped), and a directory with no ESI file
// at all is an error (a wrong path or a checkout without its files), not "0 files" and success.
// Version-control and tool folders (hidden: .git, .svn, .cache …) and CMake build trees (a
// folder holding CMakeCache.txt, whatever its name) are not walked: they hold copies and
// generated files, not the sources the run is about. The directory given itself is always walked.

#include <filesystem>
#include <vector>

#include "esi/diagnostic.hpp"

namespace esi::lint_detail {

// Appends the *.xml files (case-insensitive extension) under `dir`, sorted; each problem is an
// io-error diagnostic naming the directory it concerns. Symbolic links to directories are not
// followed (no loops); links to files are.
void collect_xml_files(const std::filesystem::path& dir, std::vector<std::filesystem::path>& out, Diagnostics& diagnostics);

}  // namespace esi::lint_detail
