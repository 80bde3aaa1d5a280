#pragma once
/// \file OutputStaging.hpp
/// When a run's files become visible. Every writer writes "<file>.part" and publishes it under its
/// final name. Outside a staging scope publish() renames at once. Inside one (a whole run:
/// adapt::AdaptiveSimulation::run) the final names are only recorded, and commit() at the end of
/// the run makes them visible together: it renames every staged file, then removes the files an
/// earlier run left under the names retired with retireOnCommit() that this run did not write
/// again. A run that fails (its scope ends without commit) removes its staged files (and the
/// output directories it created, if empty), so the
/// results of an earlier run in the same directory stay as they were. The state is per process
/// (the output files are written on rank 0).
#include <functional>
#include <string>
#include <vector>

#include "signorini/core/Interrupt.hpp"

namespace signorini::io {

/// A staging scope. Scopes nest: an inner one joins the outer one, and only the outermost commits
/// or discards.
class OutputStaging {
 public:
  OutputStaging();
  /// Removes the staged files unless commit() was called.
  ~OutputStaging();
  OutputStaging(const OutputStaging&) = delete;
  OutputStaging& operator=(const OutputStaging&) = delete;
  /// Outermost scope: renames the staged files, then removes the retired ones. If a rename fails
  /// it removes all files of the run (renamed or not), retires nothing and throws
  /// core::UserError naming the file. Inner scopes: nothing.
  void commit();

 private:
  bool outermost_;
  bool done_ = false;
};

/// While it lives, this process holds "<base>.lock" (an exclusive flock), so that a second run under
/// the same output base, in another process, fails at its start (core::UserError) instead of
/// retiring the first run's ".part" files while that run is still writing them. The file is
/// removed when the lock is released; one that a killed run left is taken over (the kernel
/// released its lock with the process; the signal handler leaves it, which would let a second run in
/// while this one still writes). Where the file system has no locks, or the file cannot
/// be created, the run goes on without the lock, with a warning.
class OutputLock {
 public:
  /// Takes "<base>.lock"; throws core::UserError if another process holds it (a warning instead where it cannot
  /// be created or locked).
  explicit OutputLock(const std::string& base);
  ~OutputLock();
  OutputLock(const OutputLock&) = delete;
  OutputLock& operator=(const OutputLock&) = delete;

 private:
  std::string path_;
  int fd_ = -1;
};

/// Directories the open scope's run created for its output (parents first): a run that fails
/// removes them again if they are empty. Outside a scope: nothing.
void removeOnFailure(const std::vector<std::string>& createdDirectories);
/// Renames \p part to \p finalPath now, or at the commit of the open scope.
void publish(const std::string& part, const std::string& finalPath);
/// Removes the published file \p finalPath (in a scope: its staged file, or nothing).
void unpublish(const std::string& finalPath);
/// Gives the published file \p from the name \p to (in a scope: changes the recorded final name).
void republish(const std::string& from, const std::string& to);
/// Removes the files in the directory of \p basePath whose names are the name of \p basePath
/// followed by a suffix that \p matches accepts, except those published in the open scope: now
/// outside a scope, at its commit inside one.
void retireOnCommit(const std::string& basePath, const std::function<bool(const std::string& suffix)>& matches);
/// Whether "<base><suffix>" is a file that a run with output base "<base>" writes: its step and
/// cycle tables ("<base>.steps.csv", "<base>.cycles.csv"), its Exodus series ("<base>.e",
/// "<base>.e-s.<digits>") and those files of single cycles ("<base>.cycle<digits>.steps.csv", ...),
/// also as the ".part" files that a killed run leaves.
bool isRunOutputSuffix(std::string suffix);
/// Whether \p suffix is ".e-s.<digits>", the suffix of the files after the first of an Exodus series.
bool isExodusSeriesSuffix(const std::string& suffix);
/// The longest suffix (".part" included) of the files a run with output base "<base>" writes:
/// ".steps.csv.part" without adaptivity; with it (\p adaptive), ".cycles.csv.part" or
/// ".cycle<l>.steps.csv.part" of the last cycle l < \p cycles - 1 that has files of its own. (An
/// Exodus series' ".e-s.NNNN.part" is shorter below 100000 files.)
std::string longestRunOutputSuffix(bool adaptive, int cycles);
/// Throws core::UserError naming \p key (the basename's) if the file name of "<base><suffix>" is
/// longer than the file system of its folder (or of the nearest folder above it that exists)
/// allows (NAME_MAX), naming \p folderKey if a folder name of \p base is, and both if the whole
/// path is longer than PATH_MAX.
void checkOutputNameLength(const std::string& base, const std::string& suffix, const std::string& key,
                           const std::string& folderKey);

}  // namespace signorini::io
