#pragma once
// What a writing run creates and must not leave behind when it is interrupted: a temporary file
// between getting its name and being renamed over its target, a directory it created, the lock
// file of an output directory. The writers register each while it exists; a tool that wants
// them removed on SIGINT, SIGTERM and SIGHUP calls install_leftover_cleanup() once at start. The
// library itself installs no signal handler: signals belong to the program.
// SIGKILL cannot be caught: a run killed with it may leave a complete temporary file
// (.NAME.tmpNNN, named just before its rename) or an empty lock file (docs/reliability.md).

namespace esi {

// Installs handlers for SIGINT, SIGTERM and SIGHUP that remove every registered leftover and
// then let the signal end the process as it would have (the exit status still says which).
void install_leftover_cleanup();

// Removes every registered leftover: files first, then directories that are empty.
// Async-signal-safe; a signal handler of the program's own may call it.
void remove_registered_leftovers() noexcept;

}  // namespace esi
