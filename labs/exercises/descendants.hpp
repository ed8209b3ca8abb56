#pragma once
// Ending every process a student's program leaves behind, wherever it went. numlab is a child
// subreaper (prctl PR_SET_CHILD_SUBREAPER, set by ChildSession), so a process whose parent dies
// comes to numlab, even one that left the program's group and session (setsid) or was double-forked:
// these functions find numlab's children in /proc, kill and reap them, then the children they leave,
// until none is left. Everything here is async-signal-safe (system calls only, no allocation), so
// numlab's signal handlers use it too.

#include <sys/types.h>

namespace numlab::exercises {

// The running programs' leaders (ChildProcess), which end_adopted_children(true) spares.
void register_running_program(pid_t leader);
void unregister_running_program(pid_t leader);

// Kills (SIGKILL) and reaps every child of this process, except the running programs' leaders when
// `spare_running_programs`, level by level until /proc lists none (at most 10,000 rounds). Returns
// how many it ended.
int end_adopted_children(bool spare_running_programs);

// Removes the folder `path` and everything in it (symbolic links are removed, not followed), in a
// bounded number of steps; true when it is gone.
bool remove_tree(const char* path);

}  // namespace numlab::exercises
