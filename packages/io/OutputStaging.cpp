#include "signorini/io/OutputStaging.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <climits>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <map>
#include <set>
#include <system_error>
#include <utility>
#include <vector>

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include "signorini/core/Error.hpp"
#include "signorini/core/StringTools.hpp"

namespace signorini::io {
namespace fs = std::filesystem;

namespace {

struct Retirement {
  std::string basePath;
  std::function<bool(const std::string&)> matches;
};

/// A file or folder of the run, which a Ctrl-C removes at once (core::RemovedOnSignal).
struct RunPath {
  std::string path;
  core::RemovedOnSignal removedOnSignal;
  RunPath(const std::string& p, bool directory = false) : path(p), removedOnSignal(p, directory) {}
};

struct Staging {
  int depth = 0;
  std::map<std::string, RunPath> partOf;  // final path -> staged file
  std::vector<Retirement> retired;
  std::vector<RunPath> createdDirectories;  // outermost first

  /// Forgets the run's files and folders.
  void clear() {
    partOf.clear();
    retired.clear();
    createdDirectories.clear();
  }
};

Staging& staging() {
  static Staging s;
  return s;
}

/// The files retirement \p r names, except those in \p keep (compared as normalised paths).
std::vector<fs::path> retiredFiles(const Retirement& r, const std::set<fs::path>& keep) {
  const fs::path base(r.basePath);
  const fs::path directory = base.has_parent_path() ? base.parent_path() : fs::path(".");
  const std::string stem = base.filename().string();
  std::vector<fs::path> files;
  std::error_code ec;
  fs::directory_iterator it(directory, ec), end;
  for (; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (name.size() <= stem.size() || name.compare(0, stem.size(), stem) != 0) continue;
    if (!r.matches(name.substr(stem.size()))) continue;
    if (keep.count((directory / name).lexically_normal())) continue;
    std::error_code regular;
    if (fs::is_regular_file(it->path(), regular)) files.push_back(it->path());
  }
  return files;
}

std::string renameError(const std::string& part, const std::string& finalPath, const std::error_code& ec) {
  return "cannot rename output file '" + part + "' to '" + finalPath + "': " + ec.message();
}

}  // namespace

bool isExodusSeriesSuffix(const std::string& suffix) {
  const std::string series = ".e-s.";
  return suffix.size() > series.size() && suffix.compare(0, series.size(), series) == 0 &&
         std::all_of(suffix.begin() + static_cast<long>(series.size()), suffix.end(),
                     [](unsigned char c) { return std::isdigit(c) != 0; });
}

bool isRunOutputSuffix(std::string suffix) {
  const std::string part = ".part";  // left by a run that was killed
  if (suffix.size() > part.size() && core::endsWith(suffix, part))
    suffix.resize(suffix.size() - part.size());
  if (suffix.rfind(".cycle", 0) == 0) {  // ".cycle<digits>" first: a file of that cycle follows
    size_t end = 6;
    while (end < suffix.size() && std::isdigit(static_cast<unsigned char>(suffix[end]))) ++end;
    if (end > 6) {
      suffix = suffix.substr(end);
      if (suffix == ".cycles.csv") return false;
    }
  }
  return suffix == ".steps.csv" || suffix == ".cycles.csv" || suffix == ".e" || isExodusSeriesSuffix(suffix);
}

std::string longestRunOutputSuffix(bool adaptive, int cycles) {
  const std::string cycleTable = ".cycles.csv.part";
  if (!adaptive) return ".steps.csv.part";
  if (cycles < 2) return cycleTable;
  const std::string cycleSteps = ".cycle" + std::to_string(cycles - 2) + ".steps.csv.part";
  return cycleSteps.size() > cycleTable.size() ? cycleSteps : cycleTable;
}

void checkOutputNameLength(const std::string& base, const std::string& suffix, const std::string& key,
                           const std::string& folderKey) {
  const fs::path path(base);
  const std::string name = path.filename().string() + suffix;
  // The file system's limit, asked of the folder or of its nearest existing ancestor (a --check
  // creates no folder); NAME_MAX (255 on Linux) if it does not say.
  fs::path folder = path.has_parent_path() ? path.parent_path() : fs::path(".");
  std::error_code ec;
  while (!fs::is_directory(folder, ec)) {
    if (!folder.has_parent_path() || folder.parent_path() == folder) {
      folder = folder.is_absolute() ? folder.root_path() : fs::path(".");
      break;
    }
    folder = folder.parent_path();
  }
  long limit = ::pathconf(folder.c_str(), _PC_NAME_MAX);
  if (limit <= 0) limit = NAME_MAX;
  const auto shortened = [](const std::string& s) { return s.size() > 40 ? s.substr(0, 32) + "..." : s; };
  if (path.has_parent_path())
    for (const auto& part : path.parent_path())
      if (static_cast<long>(part.string().size()) > limit)
        SIGNORINI_USER_ERROR(folderKey << " '" << path.parent_path().string() << "': the folder name '"
                                       << shortened(part.string()) << "' has " << part.string().size()
                                       << " characters, more than the " << limit
                                       << " the file system allows (NAME_MAX)");
  if (static_cast<long>(name.size()) > limit) {
    const std::string stem = path.filename().string();
    SIGNORINI_USER_ERROR(key << " '" << shortened(stem) << "' (" << stem.size()
                             << " characters) is too long: with the suffix '" << suffix << "' of the run's files a file "
                             << "name has " << name.size() << " characters, more than the " << limit
                             << " the file system allows (NAME_MAX); choose a shorter basename");
  }
  const std::string full = fs::absolute(path, ec).string() + suffix;
  if (full.size() >= PATH_MAX)
    SIGNORINI_USER_ERROR(folderKey << " and " << key << ": the run's file '" << shortened(full) << "' has a path of "
                                   << full.size() << " characters, more than the " << PATH_MAX - 1
                                   << " the system allows (PATH_MAX)");
}

OutputStaging::OutputStaging() : outermost_(staging().depth == 0) { ++staging().depth; }

OutputStaging::~OutputStaging() {
  auto& s = staging();
  --s.depth;
  if (!outermost_ || done_) return;
  std::error_code ec;
  for (const auto& [finalPath, part] : s.partOf) fs::remove(part.path, ec);
  // fs::remove of a directory is rmdir: it stays if something else was put there meanwhile.
  for (auto it = s.createdDirectories.rbegin(); it != s.createdDirectories.rend(); ++it) fs::remove(it->path, ec);
  s.clear();
}

void OutputStaging::commit() {
  if (!outermost_ || done_) return;
  done_ = true;
  auto& s = staging();
  auto partOf = std::move(s.partOf);
  auto retired = std::move(s.retired);
  const core::SignalRemovalPause pause;  // the renames run to their end; the run keeps its files
  s.clear();
  // The staged files first; if one cannot take its name, the run's files all go (those renamed
  // already and the others) and nothing is retired.
  std::vector<std::string> renamed;
  std::error_code ec;
  for (const auto& [finalPath, part] : partOf) {
    fs::rename(part.path, finalPath, ec);
    if (!ec) {
      renamed.push_back(finalPath);
      continue;
    }
    const std::string error = renameError(part.path, finalPath, ec);
    std::error_code ignored;
    for (const auto& f : renamed) fs::remove(f, ignored);
    for (const auto& entry : partOf) fs::remove(entry.second.path, ignored);
    SIGNORINI_USER_ERROR(error);
  }
  std::set<fs::path> keep;
  for (const auto& f : renamed) keep.insert(fs::path(f).lexically_normal());
  for (const auto& r : retired)
    for (const auto& f : retiredFiles(r, keep)) fs::remove(f, ec);
}

void removeOnFailure(const std::vector<std::string>& createdDirectories) {
  auto& s = staging();
  if (s.depth == 0) return;
  for (const auto& directory : createdDirectories) s.createdDirectories.emplace_back(directory, true);
}

void publish(const std::string& part, const std::string& finalPath) {
  auto& s = staging();
  if (s.depth > 0) {
    auto it = s.partOf.find(finalPath);
    std::error_code ec;
    if (it == s.partOf.end()) {
      s.partOf.emplace(finalPath, part);
    } else if (it->second.path != part) {  // written again in this run
      fs::remove(it->second.path, ec);
      it->second = RunPath(part);
    }
    return;
  }
  std::error_code ec;
  fs::rename(part, finalPath, ec);
  if (ec) {
    core::throwIfSignalled();  // the signal's handler removed the file
    SIGNORINI_USER_ERROR(renameError(part, finalPath, ec));
  }
}

void unpublish(const std::string& finalPath) {
  auto& s = staging();
  std::error_code ec;
  if (s.depth > 0) {
    auto it = s.partOf.find(finalPath);
    if (it == s.partOf.end()) return;  // an earlier run's file stays until the commit retires it
    fs::remove(it->second.path, ec);
    s.partOf.erase(it);
    return;
  }
  fs::remove(finalPath, ec);
}

void republish(const std::string& from, const std::string& to) {
  auto& s = staging();
  if (s.depth > 0) {
    auto it = s.partOf.find(from);
    SIGNORINI_ASSERT(it != s.partOf.end(), "republish: '" << from << "' was not published in this run");
    const RunPath part = std::move(it->second);  // registered until publish registers it again
    s.partOf.erase(it);
    publish(part.path, to);
    return;
  }
  publish(from, to);
}

void retireOnCommit(const std::string& basePath, const std::function<bool(const std::string& suffix)>& matches) {
  auto& s = staging();
  Retirement r{basePath, matches};
  if (s.depth > 0) {
    s.retired.push_back(std::move(r));
    return;
  }
  std::error_code ec;
  for (const auto& f : retiredFiles(r, {})) fs::remove(f, ec);
}

OutputLock::OutputLock(const std::string& base) : path_(base + ".lock") {
  // A file system without locks (some network or FUSE mounts) only loses the safety net.
  const auto withoutLock = [&](const char* what, int error) {
    std::cerr << "signorini: warning: cannot " << what << " '" << path_ << "' (" << std::strerror(error)
              << "): a second run under this output base would not be refused" << std::endl;
  };
  for (;;) {
    fd_ = ::open(path_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd_ < 0) {
      withoutLock("create the lock file", errno);
      return;
    }
    if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
      const int error = errno;
      ::close(fd_);
      fd_ = -1;
      if (error == EWOULDBLOCK)
        SIGNORINI_USER_ERROR("another run is writing its results under the output base '"
                             << base << "' (it holds '" << path_
                             << "'); wait for it to end, or give this run its own Output/Basename or --output-dir");
      ::unlink(path_.c_str());
      withoutLock("lock", error);
      return;
    }
    // The holder before us may have removed the file between our open and our lock: then the lock
    // is on a file without a name, and a third run could lock a new one. Take the named file.
    struct stat held, named;
    if (::fstat(fd_, &held) == 0 && ::stat(path_.c_str(), &named) == 0 && held.st_dev == named.st_dev &&
        held.st_ino == named.st_ino) {
      return;
    }
    ::close(fd_);
    fd_ = -1;
  }
}

OutputLock::~OutputLock() {
  if (fd_ < 0) return;
  ::unlink(path_.c_str());  // while still locked, so no other run takes the name in between
  ::close(fd_);
}

}  // namespace signorini::io
