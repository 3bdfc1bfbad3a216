#include "formats/output_set.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/statvfs.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <thread>

#include "common/errors.h"
#include "common/input_file.h"
#include "formats/commit_record.h"
#include "formats/storage.h"

namespace brdfbake {

namespace {

// ---- what the signal handler may touch: fixed buffers, no allocation -----------------------
constexpr int kMaxPaths = kMaxFilesPerSet + 1;  // every temporary, and the lock's holder line
constexpr int kPathLen = 4096;
char gPaths[kMaxPaths][kPathLen];  // temporaries to unlink
char gDirs[64][kPathLen];          // directories we created, to rmdir (deepest last)
volatile sig_atomic_t gNumPaths = 0, gNumDirs = 0;
char gWhat[1024];

void copyTo(char* dst, const std::string& s) {
  size_t n = std::min(s.size(), static_cast<size_t>(kPathLen - 1));
  std::memcpy(dst, s.data(), n);
  dst[n] = '\0';
}

void put(const char* s) {
  ssize_t r = ::write(2, s, std::strlen(s));
  (void)r;
}

extern "C" void onInterrupt(int sig) {
  for (int i = 0; i < gNumPaths; ++i) ::unlink(gPaths[i]);
  for (int i = gNumDirs - 1; i >= 0; --i) ::rmdir(gDirs[i]);
  put("brdfbake: interrupted (");
  put(sig == SIGINT ? "SIGINT" : sig == SIGTERM ? "SIGTERM" : "SIGHUP");
  put("): ");
  put(gWhat);
  put("; nothing was written\n");
  ::_exit(128 + sig);
}

const int kSignals[] = {SIGINT, SIGTERM, SIGHUP};

sigset_t interruptSet() {
  sigset_t set;
  sigemptyset(&set);
  for (int s : kSignals) sigaddset(&set, s);
  return set;
}

std::string errnoText(int err) { return std::strerror(err); }

// A copy of `from` at `to` (a new file), synced; false with errno set when it cannot be made.
bool copyFile(const std::string& from, const std::string& to) {
  const int in = ::open(from.c_str(), O_RDONLY | O_CLOEXEC);
  if (in < 0) return false;
  const int out = ::open(to.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
  if (out < 0) {
    const int err = errno;
    ::close(in);
    errno = err;
    return false;
  }
  char buf[1 << 16];
  bool ok = true;
  for (;;) {
    ssize_t n = ::read(in, buf, sizeof buf);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      ok = n == 0;
      break;
    }
    for (ssize_t done = 0; ok && done < n;) {
      ssize_t w = ::write(out, buf + done, static_cast<size_t>(n - done));
      if (w < 0 && errno == EINTR) continue;
      ok = w > 0;
      if (ok) done += w;
    }
    if (!ok) break;
  }
  const int err = ok ? 0 : errno;
  ok = ok && ::fsync(out) == 0;
  const int err2 = ok ? 0 : (err ? err : errno);
  ::close(in);
  ::close(out);
  if (!ok) {
    ::unlink(to.c_str());
    errno = err2;
  }
  return ok;
}

// The backup of a file the commit replaces: a hard link, or where the file system has none (FAT,
// some network and FUSE file systems: EPERM, ENOTSUP, EXDEV, EMLINK, ENOSYS) a copy.
// BRDFBAKE_TEST_NO_HARDLINKS=1 makes link() fail as on such a file system (tests/commit_test.cpp).
bool keepBackup(const std::string& path, const std::string& backup) {
  const char* noLinks = std::getenv("BRDFBAKE_TEST_NO_HARDLINKS");
  if (noLinks && *noLinks == '1')
    errno = EPERM;
  else if (::link(path.c_str(), backup.c_str()) == 0)
    return true;
  if (errno != EPERM && errno != ENOTSUP && errno != EOPNOTSUPP && errno != EXDEV && errno != EMLINK && errno != ENOSYS)
    return false;
  return copyFile(path, backup);
}

std::string parentOf(const std::string& p) {
  size_t slash = p.find_last_of('/');
  if (slash == std::string::npos) return ".";
  if (slash == 0) return "/";
  return p.substr(0, slash);
}

bool isDir(const std::string& p, bool* exists) {
  struct stat st {};
  *exists = ::stat(p.c_str(), &st) == 0;
  return *exists && S_ISDIR(st.st_mode);
}

// Removes what a failed commit left: temporaries, then created directories, deepest first.
void cleanUp(const std::vector<std::string>& temps, const std::vector<std::string>& created) {
  for (const auto& t : temps) ::unlink(t.c_str());
  for (auto it = created.rbegin(); it != created.rend(); ++it) ::rmdir(it->c_str());
}

}  // namespace

uint64_t freeBytesAt(const std::string& dir, std::string* where) {
  std::string cur = dir.empty() ? "." : dir;
  struct statvfs st {};
  while (::statvfs(cur.c_str(), &st) != 0) {
    const size_t slash = cur.find_last_of('/');
    if (slash == std::string::npos) {
      cur = ".";
      if (::statvfs(cur.c_str(), &st) != 0) return UINT64_MAX;
      break;
    }
    cur = slash == 0 ? "/" : cur.substr(0, slash);
  }
  if (where) *where = cur;
  return static_cast<uint64_t>(st.f_bavail) * st.f_frsize;
}

void checkOutputDir(const std::string& dir) {
  if (dir.empty()) throw Error(kExitUsage, "-o: empty directory name");
  std::string p = dir;
  while (p.size() > 1 && p.back() == '/') p.pop_back();
  bool exists = false;
  // the nearest existing ancestor (or dir itself) must be a writable directory
  std::string cur = p;
  while (true) {
    struct stat lst {};
    if (::lstat(cur.c_str(), &lst) == 0 && S_ISLNK(lst.st_mode) && ::stat(cur.c_str(), &lst) != 0)
      throw Error(kExitCantCreat,
                  "-o: '" + cur + "' is a symbolic link to nothing (a dangling link): give a directory");
    if (isDir(cur, &exists)) break;
    if (exists) throw Error(kExitCantCreat, "-o: '" + cur + "' exists and is not a directory");
    std::string up = parentOf(cur);
    if (up == cur) break;
    cur = up;
  }
  if (::access(cur.c_str(), W_OK | X_OK) != 0)
    throw Error(kExitCantCreat, "-o: cannot write in '" + cur + "': " + errnoText(errno));
}

void checkReplaceableFile(const std::string& path, const std::string& option) {
  if (path.empty()) throw Error(kExitUsage, option + ": empty file name");
  struct stat st {};
  if (::lstat(path.c_str(), &st) == 0 && !S_ISREG(st.st_mode))
    throw Error(kExitCantCreat, option + " " + path + ": " +
                                    (S_ISLNK(st.st_mode) ? std::string("a symbolic link") : fileTypeName(st.st_mode)) +
                                    ", not a regular file; it would be replaced when the bake succeeds");
  const std::string parent = parentOf(path);
  try {
    checkOutputDir(parent);
  } catch (const Error& e) {
    throw Error(kExitCantCreat, option + " " + path + ": " + std::string(e.what()).substr(4));  // drop "-o: "
  }
}

void guardInterrupts(const std::string& what) {
  std::string w = what.substr(0, sizeof gWhat - 1);
  std::memcpy(gWhat, w.c_str(), w.size() + 1);
  gNumPaths = 0;
  gNumDirs = 0;
  struct sigaction sa {};
  sa.sa_handler = onInterrupt;
  sigemptyset(&sa.sa_mask);
  for (int s : kSignals) sigaddset(&sa.sa_mask, s);  // one handler at a time
  for (int s : kSignals) {
    struct sigaction old {};
    ::sigaction(s, nullptr, &old);
    if (old.sa_handler == SIG_IGN) continue;  // e.g. nohup: keep ignoring
    ::sigaction(s, &sa, nullptr);
  }
}

void commitOutputs(const std::string& dir, const std::vector<OutputFile>& files, bool wait) {
  if (files.size() > static_cast<size_t>(kMaxFilesPerSet))
    throw Error(kExitUsage, "too many files in one set (" + std::to_string(files.size()) + "; at most " +
                                std::to_string(kMaxFilesPerSet) +
                                " land together): ask for fewer tables or formats per run");
  checkOutputDir(dir);
  // mkdir -p, remembering what we created; the handler sees each one before it exists
  std::vector<std::string> created, chain;
  std::string p = dir;
  while (p.size() > 1 && p.back() == '/') p.pop_back();
  for (std::string cur = p;; cur = parentOf(cur)) {
    bool exists = false;
    if (isDir(cur, &exists)) break;
    chain.push_back(cur);
    if (parentOf(cur) == cur) break;
  }
  for (auto it = chain.rbegin(); it != chain.rend(); ++it) {
    if (gNumDirs < 64) {
      copyTo(gDirs[gNumDirs], *it);
      gNumDirs = gNumDirs + 1;
    }
    if (::mkdir(it->c_str(), 0777) != 0 && errno != EEXIST) {
      int err = errno;
      cleanUp({}, created);
      throwFileError(err, "-o: cannot create directory '" + *it + "'");  // no space or inodes: 74
    }
    created.push_back(*it);
  }
  // every file lands in `dir` itself: the commit record names them relative to it
  struct stat dirSt {};
  ::stat(p.c_str(), &dirSt);
  for (const auto& f : files) {
    struct stat st {};
    if (::stat(parentOf(f.path).c_str(), &st) != 0 || st.st_dev != dirSt.st_dev || st.st_ino != dirSt.st_ino) {
      cleanUp({}, created);
      throw Error(kExitSoftware, "internal: " + f.path + " is not in the output directory " + dir);
    }
  }

  // the set fits in the free space (streamed writers that know no bound check their own)
  uint64_t need = 0;
  for (const auto& f : files)
    need += f.bytesBound ? f.bytesBound
            : f.image    ? tableExrBytesBound(f.image->width, f.image->height, f.image->planes.size(), f.half)
                         : 0;
  const uint64_t free = need > 0 ? freeBytesAt(p) : UINT64_MAX;
  if (need > free) {
    cleanUp({}, created);
    char msg[512];
    std::snprintf(msg, sizeof msg,
                  "-o %s: not enough space: the %zu file(s) may need up to %.2f MB, %.2f MB free; "
                  "nothing was written",
                  dir.c_str(), files.size(), need / 1e6, free / 1e6);
    throw Error(kExitIoErr, msg);
  }

  // one writer at a time; then finish or sweep what a killed writer left
  std::vector<std::string> temps;
  std::unique_ptr<DirLock> lock;
  try {
    lock = std::make_unique<DirLock>(p, wait);
    if (gNumPaths < kMaxPaths) {  // the handler removes the holder line with the rest
      copyTo(gPaths[gNumPaths], lock->infoPath());
      gNumPaths = gNumPaths + 1;
    }
    recoverDirectory(p);
  } catch (...) {
    lock.reset();
    cleanUp({}, created);
    throw;
  }

  // every file to its temporary, synced
  try {
    for (const auto& f : files) {
      // created and registered with the signals held, so the handler knows every temporary
      sigset_t set = interruptSet(), prev;
      ::sigprocmask(SIG_BLOCK, &set, &prev);
      std::string tmp;
      try {
        tmp = makeTemporaryFor(f.path);
      } catch (...) {
        ::sigprocmask(SIG_SETMASK, &prev, nullptr);
        throw;
      }
      copyTo(gPaths[gNumPaths], tmp);
      gNumPaths = gNumPaths + 1;
      ::sigprocmask(SIG_SETMASK, &prev, nullptr);
      temps.push_back(tmp);
    }
    // the writers in order (they may share a device or a stream), then the images together
    std::vector<ExrTemporary> images;
    for (size_t k = 0; k < files.size(); ++k) {
      if (files[k].write)
        files[k].write(temps[k]);
      else
        images.push_back({temps[k], files[k].path, files[k].image, files[k].half});
    }
    writeTableExrTemporaries(images);
  } catch (const Error& e) {
    lock.reset();  // its holder line goes first, so that a directory we created is empty again
    cleanUp(temps, created);
    throw Error(e.code(), std::string(e.what()) + "; nothing was written");
  } catch (...) {
    lock.reset();
    cleanUp(temps, created);
    throw;
  }
  // For tests of interrupted writes: hold here, every temporary written, nothing renamed yet.
  if (const char* hold = std::getenv("BRDFBAKE_TEST_HOLD_BEFORE_COMMIT_MS"))
    std::this_thread::sleep_for(std::chrono::milliseconds(std::atoi(hold)));
  // For tests of interleaved writers: a pause between renames.
  const char* renameDelay = std::getenv("BRDFBAKE_TEST_RENAME_DELAY_MS");

  // The renames, with the interrupt signals held back until all have landed (or been undone).
  sigset_t set = interruptSet(), old;
  ::sigprocmask(SIG_BLOCK, &set, &old);
  std::vector<std::string> backups(files.size());
  std::string failure;
  ExitCode code = kExitOk;
  // keep a link to each file we replace, so a failed rename can put the set back as it was
  for (size_t k = 0; k < files.size() && failure.empty(); ++k) {
    bool exists = false;
    isDir(files[k].path, &exists);
    if (!exists) continue;
    backups[k] = temps[k] + ".old";
    if (!keepBackup(files[k].path, backups[k])) {
      failure = "cannot keep a backup of " + files[k].path + ": " + errnoText(errno);
      code = errno == ENOSPC || errno == EDQUOT || errno == EFBIG ? kExitIoErr : kExitCantCreat;
      backups[k].clear();
    }
  }
  // the record first: a run killed from here on is finished by the next one (recoverDirectory)
  std::string record;
  if (failure.empty()) {
    std::vector<std::pair<std::string, std::string>> pairs;
    for (size_t k = 0; k < files.size(); ++k) pairs.push_back({temps[k], files[k].path});
    try {
      record = writeCommitRecord(p, pairs);
    } catch (const Error& e) {
      failure = e.what();
      code = e.code();
    }
    testKillPoint("record");
  }
  size_t landed = 0;
  for (; landed < files.size() && failure.empty(); ++landed) {
    if (landed > 0 && renameDelay) std::this_thread::sleep_for(std::chrono::milliseconds(std::atoi(renameDelay)));
    if (std::rename(temps[landed].c_str(), files[landed].path.c_str()) != 0) {
      failure = "cannot create " + files[landed].path + ": " + errnoText(errno);
      code = errno == ENOSPC || errno == EDQUOT || errno == EFBIG ? kExitIoErr : kExitCantCreat;
      break;
    }
    testKillPoint("rename:" + std::to_string(landed + 1));
  }
  if (failure.empty()) testKillPoint("renamed");
  if (!failure.empty()) {
    for (size_t k = 0; k < landed; ++k) {
      if (!backups[k].empty()) {
        std::rename(backups[k].c_str(), files[k].path.c_str());
        backups[k].clear();
      } else {
        ::unlink(files[k].path.c_str());
      }
    }
  }
  for (const auto& b : backups)
    if (!b.empty()) ::unlink(b.c_str());
  if (!record.empty()) removeCommitRecord(p, record);  // landed, or put back as it was
  lock.reset();
  if (!failure.empty()) cleanUp(temps, created);
  // Done with what the handler would remove. A signal that arrived meanwhile is delivered with its
  // default action once unblocked: the set has landed whole (or not at all) by then.
  gNumPaths = 0;
  gNumDirs = 0;
  for (int s : kSignals) {
    struct sigaction cur {};
    ::sigaction(s, nullptr, &cur);
    if (cur.sa_handler == onInterrupt) {
      struct sigaction dfl {};
      dfl.sa_handler = SIG_DFL;
      ::sigaction(s, &dfl, nullptr);
    }
  }
  ::sigprocmask(SIG_SETMASK, &old, nullptr);
  if (!failure.empty()) throw Error(code, failure + "; nothing was written");
}

void checkNotAnInput(const std::string& path, const std::vector<std::string>& inputs, const std::string& option) {
  struct stat out {};
  if (::stat(path.c_str(), &out) != 0) return;  // not there: it cannot be one of them
  for (const std::string& in : inputs) {
    struct stat st {};
    if (::stat(in.c_str(), &st) == 0 && st.st_dev == out.st_dev && st.st_ino == out.st_ino)
      throw Error(kExitCantCreat, option + " " + path + ": is " + (in == path ? "" : "the same file as ") +
                                      (in == path ? "" : in + ", ") +
                                      "an input of this command; it would be replaced by its output");
  }
}

void writeTextFile(const std::string& path, const std::string& text) {
  // under the directory's lock, as every writer there: a bake's sweep never meets it half written
  const std::string parent = parentOf(path);
  DirLock lock(parent.empty() ? "." : parent, true);
  replaceWhole(path, [&](const std::string& tmp) {
    TempFileWriter out(tmp, path);
    out.write(text);
    out.finish();
  });
}

}  // namespace brdfbake
