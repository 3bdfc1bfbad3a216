#include "formats/commit_record.h"

#include <dirent.h>
#include <fcntl.h>
#include <signal.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <thread>

#include "common/errors.h"

namespace brdfbake {

namespace {

std::string joinPath(const std::string& dir, const std::string& name) {
  return dir.empty() || dir.back() == '/' ? dir + name : dir + "/" + name;
}

std::string baseName(const std::string& p) {
  size_t slash = p.find_last_of('/');
  return slash == std::string::npos ? p : p.substr(slash + 1);
}

void syncDir(const std::string& dir) {
  int fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd >= 0) {
    ::fsync(fd);
    ::close(fd);
  }
}

// This process's command line, for the lock's holder line: "brdfbake bake -o out".
std::string commandLine() {
  std::ifstream in("/proc/self/cmdline", std::ios::binary);
  std::string raw((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>()), out;
  for (char c : raw) out += c == '\0' ? ' ' : (c == '\n' ? ' ' : c);
  while (!out.empty() && out.back() == ' ') out.pop_back();
  return out.substr(0, 300);
}

std::string holderOf(const std::string& info) {
  std::ifstream in(info);
  std::string line;
  std::getline(in, line);
  return line.empty() ? "another process" : line;
}

}  // namespace

void throwFileError(int err, const std::string& what) {
  const bool full = err == ENOSPC || err == EDQUOT || err == EFBIG;  // EFBIG: past ulimit -f
  throw Error(full ? kExitIoErr : kExitCantCreat, what + ": " + std::strerror(err));
}

unsigned currentUmask() {
  static const mode_t mask = [] {
    const mode_t m = ::umask(0);
    ::umask(m);
    return m;
  }();
  return mask;
}

void replaceWhole(const std::string& path, const std::function<void(const std::string& tmp)>& writeTemporary) {
  const std::string tmp = makeTemporaryFor(path);
  try {
    writeTemporary(tmp);
  } catch (...) {
    ::unlink(tmp.c_str());
    throw;
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    const int err = errno;
    ::unlink(tmp.c_str());
    throw Error(kExitCantCreat, "cannot create " + path + ": " + std::strerror(err));
  }
}

std::string makeTemporaryFor(const std::string& path) {
  const size_t slash = path.find_last_of('/');
  const std::string dir = slash == std::string::npos ? std::string() : path.substr(0, slash + 1);
  const std::string name = slash == std::string::npos ? path : path.substr(slash + 1);
  if (name.empty() || name == "." || name == "..")
    throw Error(kExitCantCreat, "cannot create " + path + ": not a file name");
  // `.` + name + marker + 6 must fit a file name (255 bytes): a long name is cut for its temporary
  const std::string marker = temporaryMarker();
  const size_t room = 255 - 1 - marker.size() - 6;
  std::string tmpl = dir + "." + name.substr(0, room) + marker + "XXXXXX";
  int fd = ::mkstemp(tmpl.data());
  if (fd < 0) throwFileError(errno, "cannot create a temporary for " + path);
  // mkstemp makes it 0600; a table is as readable as any file the user creates (0666 & ~umask)
  ::fchmod(fd, 0666 & ~currentUmask());
  ::close(fd);
  return tmpl;
}

std::string temporaryMarker() { return ".brdfbake-tmp-" + std::to_string(::getpid()) + "-"; }

long temporaryOwner(const std::string& name) {
  // `.<name>.brdfbake-tmp-<pid>-<6 of mkstemp's>` and its `.old` backup
  if (name.empty() || name[0] != '.') return -1;
  std::string n = name;
  if (n.size() > 4 && n.compare(n.size() - 4, 4, ".old") == 0) n.resize(n.size() - 4);
  const size_t t = n.rfind(".brdfbake-tmp-");
  if (t == std::string::npos || t == 0) return -1;
  const size_t p = t + 14, dash = n.find('-', p);
  if (dash == std::string::npos || dash == p || dash - p > 9 || n.size() - dash - 1 != 6) return -1;
  long pid = 0;
  for (size_t i = p; i < dash; ++i) {
    if (n[i] < '0' || n[i] > '9') return -1;
    pid = pid * 10 + (n[i] - '0');
  }
  return pid > 0 ? pid : -1;
}

bool ownerIsGone(long pid) { return pid > 0 && ::kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH; }

DirLock::DirLock(const std::string& dir, bool wait) : info_(joinPath(dir, kLockInfoName)) {
  fd_ = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd_ < 0) throwFileError(errno, "-o: cannot open directory '" + dir + "' to lock it");
  if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    if (errno != EWOULDBLOCK) {
      const int err = errno;
      ::close(fd_);
      throwFileError(err, "-o: cannot lock '" + dir + "'");
    }
    if (!wait) {
      const std::string who = holderOf(info_);
      ::close(fd_);
      throw Error(kExitTempFail, "-o " + dir + ": another bake is writing there (" + who +
                                     "); try again when it has finished, or leave out --no-wait to wait for it");
    }
    // a second long enough for a short bake to finish unannounced, then say once who holds it
    bool locked = false;
    for (int i = 0; i < 20 && !locked; ++i) {
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
      locked = ::flock(fd_, LOCK_EX | LOCK_NB) == 0;
    }
    if (!locked) {
      std::cerr << "brdfbake: waiting for " << dir << ": another bake is writing there (" << holderOf(info_) << ")"
                << std::endl;
      while (::flock(fd_, LOCK_EX) != 0)
        if (errno != EINTR) throwFileError(errno, "-o: cannot lock '" + dir + "'");
    }
  }
  // who holds it, for a process that waits (removed on release; a killed holder's is overwritten)
  const std::string line = "PID " + std::to_string(::getpid()) + ": " + commandLine() + "\n";
  int fd = ::open(info_.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC | O_NOFOLLOW, 0644);
  if (fd >= 0) {
    ssize_t n = ::write(fd, line.data(), line.size());
    (void)n;
    ::close(fd);
  }
}

DirLock::~DirLock() {
  ::unlink(info_.c_str());
  if (fd_ >= 0) ::close(fd_);  // releases the lock
}

void recoverDirectory(const std::string& dir) {
  const std::string record = joinPath(dir, kCommitRecordName);
  std::ifstream in(record);
  if (in) {
    // finish the renames: each temporary still there was synced before the record was written
    int finished = 0;
    std::string line;
    while (std::getline(in, line)) {
      const size_t tab = line.find('\t');
      if (tab == std::string::npos) continue;
      const std::string tmp = joinPath(dir, baseName(line.substr(0, tab)));
      const std::string target = joinPath(dir, baseName(line.substr(tab + 1)));
      if (::access(tmp.c_str(), F_OK) != 0) continue;  // renamed before the process died
      if (std::rename(tmp.c_str(), target.c_str()) != 0)
        throw Error(kExitIoErr, "cannot finish the interrupted commit in " + dir + ": rename " + tmp + " to " + target +
                                    ": " + std::strerror(errno));
      ++finished;
    }
    in.close();
    syncDir(dir);
    ::unlink(record.c_str());
    std::cerr << "brdfbake: " << dir << ": finished the commit of a bake that was killed (" << finished
              << " file(s) renamed)" << std::endl;
  }
  // sweep the temporaries and backups this tool can prove its own: its marker with the PID of a
  // process that is gone (a live one's, a writer without the lock, is left alone; so is any name
  // that only looks like ours)
  DIR* d = ::opendir(dir.c_str());
  if (!d) return;
  std::vector<std::string> sweep;
  while (dirent* e = ::readdir(d))
    if (ownerIsGone(temporaryOwner(e->d_name))) sweep.push_back(joinPath(dir, e->d_name));
  ::closedir(d);
  for (const auto& p : sweep) {
    // a report page's temporary is a directory (report/report_page.h), a table's a file
    struct stat st {};
    if (::lstat(p.c_str(), &st) == 0 && S_ISDIR(st.st_mode)) {
      // only a page's own directory name
      const std::string base = p.substr(p.find_last_of('/') + 1);
      bool page = false;
      for (const char* name : {".verify.", ".stress.", ".convergence.", ".energy."})
        page = page || base.rfind(std::string(name) + "brdfbake-tmp-", 0) == 0;
      if (!page) continue;
      std::error_code ec;
      std::filesystem::remove_all(p, ec);
      if (ec) throw Error(kExitIoErr, "cannot remove " + p + " (a temporary a killed run left): " + ec.message());
    } else if (::unlink(p.c_str()) != 0 && errno != ENOENT) {
      throw Error(kExitIoErr, "cannot remove " + p + " (a temporary a killed bake left): " + std::strerror(errno));
    }
  }
  if (!sweep.empty()) syncDir(dir);
}

std::string writeCommitRecord(const std::string& dir, const std::vector<std::pair<std::string, std::string>>& pairs) {
  std::string text;
  for (const auto& [tmp, target] : pairs) text += baseName(tmp) + "\t" + baseName(target) + "\n";
  const std::string record = joinPath(dir, kCommitRecordName);
  int fd = ::open(record.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC | O_NOFOLLOW, 0644);
  if (fd < 0) throwFileError(errno, "cannot create the commit record " + record);
  size_t done = 0;
  while (done < text.size()) {
    ssize_t n = ::write(fd, text.data() + done, text.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      const int err = n < 0 ? errno : EIO;
      ::close(fd);
      ::unlink(record.c_str());
      throwFileError(err, "cannot write the commit record " + record);
    }
    done += static_cast<size_t>(n);
  }
  if (::fsync(fd) != 0) {
    const int err = errno;
    ::close(fd);
    ::unlink(record.c_str());
    throwFileError(err, "cannot write the commit record " + record);
  }
  ::close(fd);
  syncDir(dir);  // the record is on disk before the first rename
  return record;
}

void removeCommitRecord(const std::string& dir, const std::string& record) {
  syncDir(dir);  // the renames are on disk before the record goes
  ::unlink(record.c_str());
  syncDir(dir);
}

void testKillPoint(const std::string& step) {
  const char* at = std::getenv("BRDFBAKE_TEST_KILL_AT");
  if (at && step == at) ::raise(SIGKILL);
}

}  // namespace brdfbake
