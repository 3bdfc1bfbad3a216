// One writer per output directory, and a commit that a killed run cannot leave half done
// (docs/reliability.md). commitOutputs (formats/output_set.h) uses all of it:
//  - DirLock: flock on the directory itself, released by the kernel when the process dies; a
//    second bake waits (saying once, after 1 s, who holds it) or, without waiting, exits 75;
//  - the commit record: before the first rename, the list of (temporary, target) pairs, synced;
//    removed once every rename has landed;
//  - recoverDirectory: under the lock, finishes the renames of a record a killed run left (its
//    temporaries were synced before the record was written), then removes the temporaries and
//    backups this tool can prove its own: its marker and the PID of a process that is gone.
#pragma once
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace brdfbake {

// The hidden names this tool uses in an output directory.
inline const char* const kLockInfoName = ".brdfbake-lock";        // who holds the lock (while held)
inline const char* const kCommitRecordName = ".brdfbake-commit";  // a commit in progress
// A temporary for `path` in the same directory, unique (mkstemp):
// `.<name>.brdfbake-tmp-<pid>-XXXXXX`, the marker and this process's PID saying whose it is.
// The file exists (empty) when this returns. Error(kExitCantCreat), or kExitIoErr when the file
// system is full (no space, quota or inodes).
std::string makeTemporaryFor(const std::string& path);
// Writes `path` whole or not at all, the one temporary-write sequence of every single-file writer:
// `writeTemporary(tmp)` fills a fresh temporary next to it (makeTemporaryFor), which is renamed onto
// `path`. On any failure the temporary is removed and the error goes on; a failed rename is
// Error(kExitCantCreat) naming `path`.
void replaceWhole(const std::string& path, const std::function<void(const std::string& tmp)>& writeTemporary);
// The process's umask (read once, at the first call).
unsigned currentUmask();
// The marker a temporary's name carries after `.<name>`: ".brdfbake-tmp-<pid>-".
std::string temporaryMarker();
// The PID a directory entry's name says made it, when the name is exactly this tool's temporary
// or backup form (`.<name>.brdfbake-tmp-<pid>-XXXXXX`, `.old` after a backup); -1 otherwise.
long temporaryOwner(const std::string& name);
// Whether that process is gone (no process with the PID). A sweep removes only such temporaries.
bool ownerIsGone(long pid);

class DirLock {
 public:
  // Locks `dir` (an existing directory). wait = false: Error(kExitTempFail) at once when another
  // process holds it, naming that process.
  DirLock(const std::string& dir, bool wait);
  ~DirLock();
  DirLock(const DirLock&) = delete;
  DirLock& operator=(const DirLock&) = delete;
  const std::string& infoPath() const { return info_; }

 private:
  int fd_ = -1;
  std::string info_;
};

// Under the lock: finishes an interrupted commit (prints one line to stderr saying so) and sweeps
// the temporaries of this tool's processes that are gone. Error(kExitIoErr) when a rename or removal fails.
void recoverDirectory(const std::string& dir);

// Writes and syncs the record of `pairs` (temporary, target), both paths inside `dir`; returns its
// path. Error(kExitIoErr) / Error(kExitCantCreat) when it cannot be written.
std::string writeCommitRecord(const std::string& dir, const std::vector<std::pair<std::string, std::string>>& pairs);
// Removes the record and syncs the directory.
void removeCommitRecord(const std::string& dir, const std::string& record);

// For tests of killed commits: when $BRDFBAKE_TEST_KILL_AT equals `step` ("record", "rename:N",
// "renamed"), the process sends itself SIGKILL there.
void testKillPoint(const std::string& step);

// Error(kExitIoErr) for errno values that mean the file system is full (ENOSPC, EDQUOT), else
// Error(kExitCantCreat); the message is `what` + ": " + strerror.
[[noreturn]] void throwFileError(int err, const std::string& what);

}  // namespace brdfbake
