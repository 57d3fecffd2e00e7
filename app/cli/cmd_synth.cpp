// `eigenwalker-cli synth --count N --seed S --out DIR [--format csv|bvh] …`: writes the
// synthetic population (docs/SYNTHETIC.md) as files our loaders read back, plus a
// manifest walkers.csv with each walker's parameters as attribute columns.
#include <filesystem>
#include <iostream>
#include <system_error>

#include "app/cli/checks.h"
#include "app/cli/commands.h"
#include "core/common/errors.h"
#include "core/io/atomic_write.h"
#include "core/io/bvh_writer.h"
#include "core/io/joint_csv.h"
#include "core/synth/population.h"

namespace ew::cli {
namespace {

namespace fs = std::filesystem;

struct SynthArgs {
  int count = 50;
  std::uint64_t seed = kDefaultSynthSeed;
  std::string out;
  std::string format = "csv";
  double cycles = 4.0;
  double rateHz = 120.0;
  int trials = 1;
  bool treadmill = false;
  bool force = false;
};

[[noreturn]] void badArgument(const std::string& what, const std::string& problem) {
  throw Error(ErrorKind::BadArgument, what, "", problem);
}

// The folder must be new, or empty, or replaced on purpose (--force).
void checkTarget(const fs::path& out, bool force) {
  std::error_code ec;
  if (!fs::exists(out, ec)) return;
  if (!fs::is_directory(out, ec)) badArgument(out.string(), "exists and is not a folder");
  if (!fs::is_empty(out, ec) && !force) {
    badArgument(out.string(),
                "exists and is not empty: choose another --out or add --force to replace it");
  }
}

std::string walkerComment(const SynthWalker& w, const SynthArgs& a) {
  return "SYNTHETIC walker " + w.id + " trial " + std::to_string(w.trialIndex + 1) +
         " (eigenwalker synth, seed " + std::to_string(a.seed) + "): generated, not motion capture";
}

void writeWalkerFile(const fs::path& file, const SynthWalker& w, const SynthArgs& a) {
  const JointTrial& t = w.trial;
  if (a.format == "bvh") {
    BvhWriteOptions options;
    options.toesMm = w.toesMm;
    writeBvh(file, t.positionsMm, t.rateHz, options);
    return;
  }
  writeJointCsv(
      file, t.positionsMm, t.rateHz,
      {walkerComment(w, a), "mm, x right, y forward, z up; " +
                                std::string(a.treadmill ? "walking in place (treadmill)"
                                                        : "overground, progression along +y")});
}

void writeManifest(const fs::path& file, const std::vector<SynthWalker>& walkers,
                   const std::vector<std::string>& files) {
  const auto names = synthAttributeNames();
  writeFileAtomically(file, [&](std::ostream& out) {
    out << "file,subject,source,condition";
    for (const auto& n : names) out << ',' << n;
    out << '\n';
    for (size_t i = 0; i < walkers.size(); ++i) {
      out << files[i] << ',' << walkers[i].id << ',' << kSynthSource << ',' << kSynthCondition;
      for (const auto& n : names) out << ',' << formatAttribute(walkers[i].attributes.at(n));
      out << '\n';
    }
  });
}

// Writes everything into a hidden sibling folder, then renames it into place: the target
// is never seen half-written, and an old folder (with --force) is removed only after.
void writePopulationFolder(const fs::path& out, const std::vector<SynthWalker>& walkers,
                           const SynthArgs& a) {
  const fs::path parent = out.has_parent_path() ? out.parent_path() : fs::path(".");
  const fs::path partial = parent / ("." + out.filename().string() + ".partial");
  const fs::path old = parent / ("." + out.filename().string() + ".old");
  fs::remove_all(partial);
  fs::create_directories(partial);
  try {
    std::vector<std::string> files;
    for (const SynthWalker& w : walkers) {
      files.push_back(w.trialId + "." + a.format);
      writeWalkerFile(partial / files.back(), w, a);
    }
    writeManifest(partial / "walkers.csv", walkers, files);
    fs::remove_all(old);
    if (fs::exists(out)) fs::rename(out, old);
    fs::rename(partial, out);
    fs::remove_all(old);
  } catch (...) {
    std::error_code ec;
    fs::remove_all(partial, ec);
    throw;
  }
}

int runSynth(const SynthArgs& a) {
  if (a.out.empty()) badArgument("--out", "an output folder is required");
  const fs::path out = folderPathWithoutTrailingSeparator(a.out);  // "synth/" is "synth"
  if (out.filename().empty() || out.filename() == "." || out.filename() == "..") {
    badArgument("--out", "must name a folder, got '" + a.out + "'");
  }
  checkTarget(out, a.force);
  PopulationOptions options;
  options.count = a.count;
  options.seed = a.seed;
  options.trialsPerWalker = a.trials;
  options.simulation.cycles = a.cycles;
  options.simulation.rateHz = a.rateHz;
  options.simulation.treadmill = a.treadmill;
  const std::vector<SynthWalker> walkers = generatePopulation(options);
  try {
    writePopulationFolder(out, walkers, a);
  } catch (const fs::filesystem_error& e) {
    throw Error(ErrorKind::Io, out.string(), "", e.code().message());
  }
  std::cerr << "wrote " << walkers.size() << " synthetic walker trial(s) (" << a.format << ", seed "
            << a.seed << ") and walkers.csv to " << out.string() << "\n";
  return 0;
}

}  // namespace

void addSynthCommand(CLI::App& app, int& exitCode) {
  auto args = std::make_shared<SynthArgs>();
  auto* cmd = app.add_subcommand(
      "synth",
      "Generate the synthetic walker population (docs/SYNTHETIC.md) as 15-joint CSV or "
      "BVH files plus a manifest walkers.csv");
  cmd->add_option("--out", args->out,
                  "Output folder (written to a temporary sibling, then renamed)")
      ->required();
  cmd->add_option("--count", args->count, "Number of walkers (subjects)")
      ->check(finiteIn(1, 10000))
      ->capture_default_str();
  cmd->add_option("--seed", args->seed, "Random seed (same seed, same files)")
      ->capture_default_str();
  cmd->add_option("--format", args->format, "csv (15-joint CSV) or bvh")
      ->check(CLI::IsMember({"csv", "bvh"}))
      ->capture_default_str();
  cmd->add_option("--cycles", args->cycles, "Gait cycles per trial")
      ->check(finiteIn(1.0, 100.0))
      ->capture_default_str();
  cmd->add_option("--rate", args->rateHz, "Frame rate in Hz")
      ->check(finiteIn(1.0, 10000.0))
      ->capture_default_str();
  cmd->add_option("--trials", args->trials, "Trials per walker (small trial-to-trial variation)")
      ->check(finiteIn(1, 100))
      ->capture_default_str();
  cmd->add_flag("--treadmill", args->treadmill, "Walk in place instead of overground along +y");
  cmd->add_flag("--force", args->force, "Replace a non-empty output folder");
  cmd->callback([args, &exitCode] { exitCode = runSynth(*args); });
}

}  // namespace ew::cli
