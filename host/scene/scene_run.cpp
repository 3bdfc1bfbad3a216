#include "scene/scene_run.h"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>

#include "bake/bake.h"
#include "formats/commit_record.h"
#include "formats/output_set.h"
#include "common/errors.h"
#include "formats/exr/table_file.h"
#include "scene/scene_plan.h"

namespace brdfbake {

namespace fs = std::filesystem;

namespace {

enum class Status { New, Changed, Damaged, UpToDate };

// Up to date: the header's brdf.hash is the plan's, and the whole file reads back with the texels it
// was written with (kTexelsHashAttribute; a 3D table, written streamed, carries none and is read
// whole). A truncated or altered table is damaged, and baked again.
Status statusOf(const PlannedTable& t, std::string* why = nullptr) {
  std::optional<std::string> h = readExrStringAttribute(t.path, "brdf.hash");
  if (!h) return fs::exists(t.path) ? Status::Changed : Status::New;
  if (*h != t.hash) return Status::Changed;
  try {
    const TableImage img = readTableExr(t.path);
    auto rec = img.strings.find(kTexelsHashAttribute);
    if (rec != img.strings.end() && rec->second != texelsHash(img.planes, tableExrIsHalf(t.path))) {
      if (why) *why = "its texels are not those it was written with";
      return Status::Damaged;
    }
  } catch (const Error& e) {
    if (why) *why = e.what();
    return Status::Damaged;
  }
  return Status::UpToDate;
}

const char* statusName(Status s) {
  return s == Status::New ? "new" : s == Status::Changed ? "changed" : s == Status::Damaged ? "damaged" : "up to date";
}

// EXR files in the output directory that this scene baked (brdf.scene) and no longer plans.
std::vector<std::string> staleTables(const ScenePlan& whole) {
  std::vector<std::string> stale;
  std::error_code ec;
  if (!fs::is_directory(whole.plan.outDir, ec)) return stale;
  std::vector<std::string> planned;
  for (const auto& t : whole.tables) planned.push_back(fs::weakly_canonical(t.path, ec).string());
  for (const auto& e : fs::directory_iterator(whole.plan.outDir, ec)) {
    if (!e.is_regular_file() || e.path().extension() != ".exr") continue;
    std::optional<std::string> scene = readExrStringAttribute(e.path().string(), "brdf.scene");
    if (!scene || *scene != whole.scene) continue;
    std::string canon = fs::weakly_canonical(e.path(), ec).string();
    if (std::find(planned.begin(), planned.end(), canon) == planned.end()) stale.push_back(e.path().string());
  }
  std::sort(stale.begin(), stale.end());
  return stale;
}

struct Loaded {
  ScenePlan whole, part;
};

Loaded load(const SceneOptions& o) {
  Scene scene = readScene(o.file);
  Loaded l;
  l.whole = planScene(scene, o.outDir);
  l.whole.plan.device = o.device;
  l.part = o.shards > 1 ? shardOf(l.whole, o.shard, o.shards) : l.whole;
  return l;
}

}  // namespace

int runScenePlan(const SceneOptions& o) {
  Loaded l = load(o);
  const ScenePlan& p = l.part;
  if (o.list) {
    std::error_code ec;
    for (const auto& t : p.tables) std::cout << fs::absolute(t.path, ec).string() << "\n";
    return kExitOk;
  }
  double cost = 0, toBake = 0;
  int stale = 0, fresh = 0;
  std::vector<Status> st;
  for (const auto& t : p.tables) {
    st.push_back(statusOf(t));
    cost += t.cost;
    if (st.back() != Status::UpToDate) {
      toBake += t.cost;
      ++stale;
    } else {
      ++fresh;
    }
  }
  std::cout << "scene " << p.scene << " (" << o.file << ")"
            << (o.shards > 1 ? ", shard " + std::to_string(o.shard) + "/" + std::to_string(o.shards) : "") << ": "
            << p.tables.size() << " table(s) into " << p.plan.outDir << "/, " << stale << " to bake (about "
            << fmtSeconds(toBake) << " s), " << fresh << " up to date\n";
  if (stale > static_cast<int>(kMaxFilesPerSet)) {
    const int parts = (stale + kMaxFilesPerSet - 1) / kMaxFilesPerSet * o.shards;
    std::cout << "note: " << stale << " tables to bake write more files than one set holds (" << kMaxFilesPerSet
              << "): bake them in " << parts << " parts, --shard 1/" << parts << " ... --shard " << parts << "/"
              << parts << "\n";
  }
  size_t wt = 5;
  for (const auto& t : p.tables) wt = std::max(wt, t.table.size());
  std::cout << planHeader(wt, 10);
  for (size_t i = 0; i < p.tables.size(); ++i) {
    const auto& t = p.tables[i];
    std::cout << planLine(wt, 10, t.table, t.size, t.texels, t.cost, statusName(st[i]), t.path) << "    " << t.models
              << "\n";
    for (const auto& r : t.reasons) std::cout << "    for " << r << "\n";
  }
  if (!p.leftOut.empty()) {
    std::cout << "left out:\n";
    for (const auto& s : p.leftOut) std::cout << "  " << s << "\n";
  }
  if (!p.notes.empty()) {
    std::cout << "notes:\n";
    for (const auto& s : p.notes) std::cout << "  " << s << "\n";
  }
  std::vector<std::string> old = staleTables(l.whole);
  if (!old.empty()) {
    std::cout << "no longer needed by this scene (bake --prune removes them):\n";
    for (const auto& s : old) std::cout << "  " << s << "\n";
  }
  return kExitOk;
}

int runSceneBake(const SceneOptions& o) {
  if (!o.stamp.empty()) {  // before anything is baked
    checkReplaceableFile(o.stamp, "--stamp");
    checkNotAnInput(o.stamp, {o.file}, "--stamp");
  }
  Loaded l = load(o);
  ScenePlan& p = l.part;
  Plan todo;
  todo.outDir = p.plan.outDir;
  todo.device = p.plan.device;
  todo.noWait = o.noWait;
  todo.observer = o.observer;
  int upToDate = 0;
  for (const auto& t : p.tables) {
    std::string why;
    const Status s = o.force ? Status::Changed : statusOf(t, &why);
    if (s == Status::UpToDate) {
      ++upToDate;
      continue;
    }
    if (s == Status::Damaged) std::cerr << "brdfbake: " << t.path << " is damaged (" << why << "): baking it again\n";
    todo.jobs.push_back(p.plan.jobs[t.index]);
    todo.extraStrings[t.path] = {{"brdf.hash", t.hash}, {"brdf.scene", p.scene}};
  }
  {
    const size_t parts = (todo.jobs.size() + kMaxFilesPerSet - 1) / kMaxFilesPerSet * o.shards;
    todo.shardHint = "bake the scene in " + std::to_string(parts) + " parts: --shard 1/" + std::to_string(parts) +
                     " ... --shard " + std::to_string(parts) + "/" + std::to_string(parts);
  }
  std::string label = "scene " + p.scene +
                      (o.shards > 1 ? " (shard " + std::to_string(o.shard) + "/" + std::to_string(o.shards) + ")" : "");
  if (todo.jobs.empty()) {
    std::cout << label << ": all " << upToDate << " table(s) up to date in " << p.plan.outDir << "/; nothing written\n";
  } else {
    std::vector<TableReport> reports = runPlan(todo);
    std::cout << formatReport(reports);
    std::cout << label << ": baked " << reports.size() << " table(s)";
    if (upToDate) std::cout << ", " << upToDate << " up to date (not rewritten)";
    std::cout << "\n";
  }
  // --prune writes into the directory: under its lock, after finishing a killed bake's commit and
  // sweeping the temporaries killed bakes left (formats/commit_record.h), as a bake does
  std::unique_ptr<DirLock> lock;
  if (o.prune && fs::is_directory(p.plan.outDir)) {
    lock = std::make_unique<DirLock>(p.plan.outDir, !o.noWait);
    recoverDirectory(p.plan.outDir);
  }
  std::vector<std::string> old = staleTables(l.whole);
  if (!old.empty() && !o.prune) {
    std::cout << "no longer needed by this scene (--prune removes them):\n";
    for (const auto& s : old) std::cout << "  " << s << "\n";
  }
  if (!old.empty() && o.prune) {
    // each file said once it is gone, never before: a failure leaves a true list of what was removed
    size_t removed = 0;
    for (const auto& s : old) {
      if (::unlink(s.c_str()) != 0) {
        const int err = errno;
        if (removed) std::cout << "\n";
        throwFileError(err, "--prune: cannot remove " + s + " (" + std::to_string(removed) + " of " +
                                std::to_string(old.size()) + " removed before it)");
      }
      std::cout << (removed++ ? "" : "removed, no longer needed by this scene:\n") << "  " << s << "\n";
    }
  }
  lock.reset();  // the stamp's writer takes the lock of its own directory, which may be this one
  if (!o.stamp.empty()) {
    std::string text = "# brdfbake " + label + ": the tables of the last successful bake\n";
    std::error_code ec;
    for (const auto& t : p.tables) text += fs::absolute(t.path, ec).string() + "\n";
    fs::path parent = fs::path(o.stamp).parent_path();
    if (!parent.empty()) fs::create_directories(parent, ec);
    writeTextFile(o.stamp, text);
  }
  return kExitOk;
}

}  // namespace brdfbake
