/// \file signorini.cpp
/// The signorini driver: runs one or more decks one after another.
///
///   signorini [--print-parameters] [--check] [--output-dir DIR] [--set 'Sublist/key=value']... DECK.xml [DECK2.xml ...]
///
/// Rank 0 reads each deck for all ranks; every rank validates it (so a bad deck fails everywhere
/// at once), the mesh and problem are set up, and the run writes its files under
/// <Output/Directory>/<basename> (README "Outputs": the step table, Exodus series, cycle tables).
/// A failing deck is reported and the next one still runs; the exit status is non-zero if any failed.
#include <filesystem>
#include <iomanip>
#include <map>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include <Kokkos_Macros.hpp>
#include <Tpetra_Core.hpp>
#include <Trilinos_version.h>
#include <mpi.h>
#include <p4est_config.h>

#include "signorini/core/Allocator.hpp"
#include "signorini/io/DeckReader.hpp"
#include "signorini/core/Error.hpp"
#include "signorini/core/Interrupt.hpp"
#include "signorini/io/OutputStaging.hpp"
#include "signorini/fem/ProblemData.hpp"
#include "signorini/core/ParameterTools.hpp"
#include "signorini/core/PhaseTimers.hpp"
#include "signorini/adapt/AdaptiveSimulation.hpp"

namespace {

const char* kUsage =
    "usage: signorini [options] DECK.xml [DECK2.xml ...]\n"
    "  --print-parameters        print every valid deck parameter (type, default, doc) and exit; with a deck,\n"
    "                            check it as --check does and print it as XML as the run would use it (every\n"
    "                            default filled in, --set applied): a complete deck\n"
    "  --check                   validate each deck and set up its problem as a run would (the same errors),\n"
    "                            print what the run would do, and write no results\n"
    "  --output-dir DIR          write all output to DIR (overrides Output/Directory; also --output-dir=DIR)\n"
    "  --set 'Sublist/key=value' override a deck entry (repeatable, validated like the deck; also --set=...)\n"
    "  --version                 the versions of signorini and of the libraries it was built with\n"
    "  --help, -h                this text\n"
    "  --kokkos-help             Kokkos' own options (for a threaded build --kokkos-threads=N), passed to Kokkos\n"
    "  --                        the arguments after it are decks\n";

/// "signorini 0.1.0" and the libraries this executable was built with (--version).
std::string versions() {
  std::ostringstream os;
  os << "signorini " << SIGNORINI_VERSION << "\nTrilinos " << TRILINOS_VERSION_STRING << " (Kokkos devices:";
#ifdef KOKKOS_ENABLE_SERIAL
  os << " Serial";
#endif
#ifdef KOKKOS_ENABLE_OPENMP
  os << " OpenMP";
#endif
#ifdef KOKKOS_ENABLE_THREADS
  os << " Threads";
#endif
#ifdef KOKKOS_ENABLE_CUDA
  os << " Cuda";
#endif
#ifdef KOKKOS_ENABLE_HIP
  os << " HIP";
#endif
  os << "), p4est " << P4EST_VERSION;
  char mpi[MPI_MAX_LIBRARY_VERSION_STRING];
  int length = 0;
  MPI_Get_library_version(mpi, &length);
  std::string library(mpi, static_cast<size_t>(length));
  library = library.substr(0, library.find_first_of(",\n"));  // "Open MPI v4.1.4"
  os << ", MPI: " << library << "\n";
  return os.str();
}

using signorini::core::ParameterList;

/// Reads and validates one deck with the command-line overrides applied.
ParameterList readDeck(const std::string& path, const std::vector<std::string>& overrides,
                       const signorini::Comm& comm) {
  ParameterList deck = signorini::io::readDeckFile(path, comm);
  const auto valid = signorini::adapt::AdaptiveSimulation::getValidParameters();
  for (const auto& o : overrides) signorini::core::applyOverride(deck, o, valid);
  signorini::core::validateDeck(deck, valid, path);
  // Valid settings without effect (e.g. Neumann Data without Neumann Segments): a warning.
  const std::string problemWarning = signorini::fem::ProblemData::checkParameters(deck.sublist("Problem"));
  if (!problemWarning.empty() && comm.getRank() == 0)
    std::cerr << "signorini: warning: " << path << ": " << problemWarning << std::endl;
  return deck;
}

}  // namespace

int main(int argc, char** argv) {
  signorini::core::keepFreedMemory();
  // Kokkos answers "--help" and "-h" with its own 60 lines of options: they are kept from it and
  // mean our usage (Kokkos' own is "--kokkos-help").
  // "--output-dir=DIR" and "--set=SPEC" are the two-word forms (GNU style).
  // After "--" every argument is a deck: none of the passes below reads one as an option.
  std::vector<std::string> words{argv[0]};
  bool ended = false;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const bool valueOption = words.back() == "--set" || words.back() == "--output-dir";
    ended = ended || (arg == "--" && !valueOption);
    bool split = false;
    for (const std::string option : {"--output-dir=", "--set="})
      if (!ended && !valueOption && !split && arg.rfind(option, 0) == 0) {
        words.push_back(option.substr(0, option.size() - 1));
        words.push_back(arg.substr(option.size()));
        split = true;
      }
    if (!split) words.push_back(arg);
  }
  std::vector<char*> args{words[0].data()};
  bool help = false, kokkosHelp = false;
  argc = static_cast<int>(words.size());
  ended = false;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = words[static_cast<size_t>(i)], before = words[static_cast<size_t>(i - 1)];
    const bool option = !ended && before != "--set" && before != "--output-dir";
    ended = ended || (option && arg == "--");
    kokkosHelp = kokkosHelp || (option && arg == "--kokkos-help");
    if ((arg == "--help" || arg == "-h") && option)
      help = true;
    else
      args.push_back(words[static_cast<size_t>(i)].data());
  }
  args.push_back(nullptr);
  argc = static_cast<int>(args.size()) - 1;
  argv = args.data();
  Tpetra::ScopeGuard tpetra(&argc, &argv);
  auto comm = Tpetra::getDefaultComm();
  const int rank = comm->getRank();
  signorini::core::installInterruptHandlers(rank == 0);
  auto& out = signorini::core::rootOut(rank);

  std::vector<std::string> decks, overrides;
  std::string outputDir;
  bool checkOnly = false, printDeck = false;
  if (kokkosHelp) return 0;  // Kokkos has printed its options
  if (help) {
    out << kUsage;
    return 0;
  }
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i], before = argv[i - 1];
    if (before == "--set" || before == "--output-dir") continue;
    if (arg == "--") break;
    if (arg == "--version") {
      out << versions();
      return 0;
    }
  }
  bool optionsEnded = false;  // after "--" every argument is a deck
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (optionsEnded) {
      decks.push_back(arg);
    } else if (arg == "--") {
      optionsEnded = true;
    } else if (arg == "--print-parameters") {
      printDeck = true;
    } else if (arg == "--check") {
      checkOnly = true;
    } else if (arg == "--output-dir" || arg == "--set") {
      if (i + 1 == argc) {
        if (rank == 0) std::cerr << "signorini: " << arg << " needs a value\n" << kUsage;
        return 2;
      }
      const std::string value = argv[++i];
      if (arg == "--set" && !signorini::core::isOverrideSpec(value)) {
        if (rank == 0) std::cerr << "signorini: --set '" << value << "': expected 'Sublist/key=value'\n";
        return 2;
      }
      // Given twice, the last one wins (as scripts that add to a command expect), with a warning.
      std::string earlier;
      // (an empty --output-dir is refused below, so a non-empty one was given)
      if (arg == "--output-dir" && !outputDir.empty() && value != outputDir) earlier = "--output-dir '" + outputDir + "'";
      const auto keyOf = [](const std::string& spec) { return spec.substr(0, spec.find('=')); };
      for (const auto& o : overrides)
        if (arg == "--set" && keyOf(o) == keyOf(value) && o != value)
          earlier = "--set '" + o + "'";
      if (!earlier.empty() && rank == 0)
        std::cerr << "signorini: warning: " << arg << " '" << value << "' replaces the earlier " << earlier << "\n";
      (arg == "--set" ? overrides.emplace_back(value) : outputDir = value);
      if (arg == "--output-dir" && outputDir.empty()) {
        if (rank == 0) std::cerr << "signorini: --output-dir needs a directory (\".\" for the working directory)\n";
        return 2;
      }
    } else if (arg.size() > 1 && arg[0] == '-') {  // "-check" is a typo, not a deck to run
      const size_t name = arg.find_first_not_of('-');
      const std::string guess =
          name == std::string::npos
              ? ""
              : signorini::core::closestName(arg.substr(name),
                                             {"print-parameters", "check", "output-dir", "set", "version", "help"});
      if (rank == 0)
        std::cerr << "signorini: unknown option " << arg << (guess.empty() ? "" : " (did you mean --" + guess + "?)")
                  << "; a deck whose name starts with '-' is given as ./" << arg << " or after --\n"
                  << kUsage;
      return 2;
    } else if (arg == "-") {
      if (rank == 0) std::cerr << "signorini: '-' is not a deck name: read a deck from standard input as /dev/stdin\n";
      return 2;
    } else {
      decks.push_back(arg);
    }
  }
  if (printDeck && decks.empty()) {
    signorini::core::printParameters(out, signorini::adapt::AdaptiveSimulation::getValidParameters());
    return 0;
  }
  if (decks.empty()) {
    if (rank == 0) std::cerr << "signorini: no deck given\n" << kUsage;
    return 2;
  }
  if (printDeck && decks.size() > 1) {  // one XML document on standard output
    if (rank == 0)
      std::cerr << "signorini: --print-parameters prints one deck: give one (or none for every valid parameter)\n";
    return 2;
  }
  checkOnly = checkOnly || printDeck;

  int failures = 0, finished = 0;  // decks that failed; decks that ran (or were checked) to their end
  std::string lastWritten;         // the deck whose results were written last
  std::map<std::string, std::string> deckOfBase;  // output bases of this batch (normalised)
  // A signal between decks (or during a --check) stops the batch; the decks after it do not run.
  auto stopIfInterrupted = [&](const std::string& where) {
    try {
      signorini::core::throwIfInterrupted(*comm);
    } catch (signorini::core::Interrupted& e) {
      if (rank == 0) std::cerr << "signorini: " << e.what() << " " << where << std::endl;
      throw;
    }
  };
  try {
    for (const auto& path : decks) {
      lastWritten.clear();
      stopIfInterrupted("before " + path + ", which did not run (nor any deck after it)");
      if (!printDeck)
        out << "signorini: " << (checkOnly ? "checking " : "running ") << path << " on " << comm->getSize() << " rank(s)"
            << std::endl;
      try {
        const auto deck = readDeck(path, overrides, *comm);
        signorini::adapt::AdaptiveSimulation sim(deck, path, outputDir, comm);
        std::error_code ec;  // links resolved: two names of one folder are one folder
        // (absolute first: weakly_canonical keeps a relative path relative while none of it exists)
        std::string base = std::filesystem::weakly_canonical(std::filesystem::absolute(sim.outputBase()), ec).string();
        if (ec) base = std::filesystem::absolute(sim.outputBase()).lexically_normal().string();
        const auto earlier = deckOfBase.emplace(base, path);
        if (!earlier.second)
          throw signorini::core::UserError("writes to the output base '" + sim.outputBase() + "' of the batch's deck " +
                                           earlier.first->second + ", whose results it would replace; give one " +
                                           "of them its own Output/Basename or run it separately");
        {  // a basename too long for the file system would fail only when the run creates its first file
          const auto& adaptivity = deck.sublist("Adaptivity");
          const bool named = !deck.sublist("Output").get<std::string>("Basename").empty();
          signorini::io::checkOutputNameLength(
              sim.outputBase(),
              signorini::io::longestRunOutputSuffix(adaptivity.get<std::string>("Strategy") != "none",
                                                    adaptivity.get<int>("Cycles")),
              named ? "Output/Basename" : "the output basename (the deck's file name; Output/Basename sets another)",
              outputDir.empty() ? "Output/Directory" : "--output-dir");
        }
        if (printDeck) {  // standard output holds the XML alone (warnings go to standard error)
          out << signorini::core::deckAsXml(sim.deck()) << std::flush;
          ++finished;
          continue;
        }
        if (checkOnly) {
          std::istringstream lines(sim.plan());
          out << "signorini: " << path << " is valid; the run would do:" << std::endl;
          for (std::string line; std::getline(lines, line);) out << "  " << line << std::endl;
          ++finished;
          continue;
        }
        const auto summary = sim.run();
        lastWritten = path;  // the files have their final names
        // An adaptive run's meshes differ from step to step: the mean over its last pass.
        const long long mean = summary.steps > 0 ? (summary.totalDofs + summary.steps / 2) / summary.steps : 0;
        out << "signorini: " << path << " done: " << summary.steps << " steps, "
            << (mean == summary.dofsPerStep ? std::to_string(mean) + " unknowns per step"
                                            : "mean " + std::to_string(mean) + " unknowns per step (" +
                                                  std::to_string(summary.dofsPerStep) + " in the last)")
            << ", " << summary.wallSeconds << " s" << std::endl;
        out << "  phase seconds:";
        for (const auto& [phase, seconds] : summary.phaseSeconds)
          out << " " << phase << " " << std::fixed << std::setprecision(3) << seconds;
        out << std::endl;
        // An Exodus series' further files (<base>.e-s.0001, ...) in one line: first, last and count.
        for (size_t i = 0; i < summary.files.size();) {
          const std::string& f = summary.files[i];
          const size_t series = f.rfind(".e-s.");
          size_t j = i + 1;
          if (series != std::string::npos)
            while (j < summary.files.size() && summary.files[j].compare(0, series + 5, f, 0, series + 5) == 0) ++j;
          if (j - i > 2)
            out << "  wrote " << f << " ... " << summary.files[j - 1] << " (" << j - i << " files of the series of "
                << f.substr(0, series + 2) << ")" << std::endl;
          else
            for (size_t m = i; m < j; ++m) out << "  wrote " << summary.files[m] << std::endl;
          i = j;
        }
        ++finished;
      } catch (signorini::core::Interrupted& e) {  // the run's files are gone; the remaining decks do not run
        if (rank == 0) std::cerr << "signorini: " << path << ": " << e.what() << "; its files were removed" << std::endl;
        throw;
      } catch (signorini::core::UserError& e) {
        ++failures;
        const std::string what = e.what();
        if (rank == 0)
          std::cerr << "signorini: error: " << (what.rfind(path, 0) == 0 ? "" : path + ": ") << what << std::endl;
      } catch (signorini::core::SolverError& e) {
        ++failures;
        if (rank == 0) std::cerr << "signorini: " << path << ": solver failure: " << e.what() << std::endl;
      } catch (std::exception& e) {  // a bug or a library error: still a clean non-zero exit
        ++failures;
        if (rank == 0)
          std::cerr << "signorini: " << path << ": unexpected error: " << signorini::core::withoutSourceLocation(e.what())
                    << std::endl;
      }
    }
    // A signal after the last deck's last check: its results, if it wrote them, are kept.
    stopIfInterrupted(checkOnly ? std::string("during the check")
                      : lastWritten.empty() ? std::string("after the last deck ended")
                                            : "after " + lastWritten + " was written (its results are kept)");
  } catch (signorini::core::Interrupted& e) {  // reported where it was caught first
    if (decks.size() > 1)
      out << "signorini: batch interrupted: " << finished << " of " << decks.size() << " deck(s) "
          << (checkOnly ? "checked" : "done") << ", " << failures << " failed, "
          << decks.size() - finished - failures << " stopped or not " << (checkOnly ? "checked" : "run") << std::endl;
    return 128 + e.signal();
  }
  if (failures) out << "signorini: " << failures << " of " << decks.size() << " deck(s) failed" << std::endl;
  return failures ? 1 : 0;
}
