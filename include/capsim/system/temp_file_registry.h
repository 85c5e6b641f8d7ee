#pragma once
// Temporary files to remove if a signal ends the process. PendingFile registers
// its temporary file here for as long as the file exists. The handler that
// remove_temp_files_on_signals installs unlinks every registered file, then
// raises the signal again with its default action, so the process still ends
// as the signal would have ended it (status, core dump) but leaves no
// ".NAME.RANDOM.tmp" behind. SIGKILL and SIGSTOP cannot be caught.
//
// The handler is async-signal-safe: the registry is a fixed array of path
// buffers, each guarded by a lock-free atomic state, and the handler only reads
// them and calls unlink(2), rmdir(2) and raise(3).
//
// A private temporary directory may be registered too: the handler removes
// the registered files first, then the directories, which are then empty if
// every file in them was registered.

#include <string>

namespace capsim {

// Registers a file; returns its slot, or -1 if the registry is full or the path
// too long (that file is then not removed on a signal; nothing else changes).
// Thread-safe.
int register_temp_file(const std::string& path);

// Forgets a slot register_temp_file returned (-1 is ignored). Thread-safe.
void unregister_temp_file(int slot);

// Installs the handler for SIGHUP, SIGINT, SIGQUIT, SIGTERM, SIGXCPU and
// SIGXFSZ (not SIGPIPE, which main ignores), except for those the process
// started with ignored (nohup, trap ''), which stay ignored. Call once, from
// main, before threads start.
void remove_temp_files_on_signals();

}  // namespace capsim
