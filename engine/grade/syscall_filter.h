// A seccomp filter for the process that runs student code: the system calls that reach the file system, start
// programs or processes, or talk to the network fail with EACCES. This is the backstop behind the Lua
// sandbox: should any binding ever open a file for a script (a new meshedit.load-like function), the child
// still cannot read a suite, a reference or write results.
//
// Invariants:
// - Installed after the child set up its pipes and limits and before it runs any student code; it cannot
//   be removed (PR_SET_NO_NEW_PRIVS, and seccomp filters only ever add restrictions).
// - Only denials: reading and writing already open descriptors, memory, time and exit still work.
// - Other architectures than the one compiled for are killed (their system call numbers differ).
#pragma once

#include <string>

namespace meshedit {

// Installs the filter in this process. Returns "" or why it could not (the kernel or a container refused);
// the caller decides whether to go on without it.
std::string install_syscall_filter();

}  // namespace meshedit
