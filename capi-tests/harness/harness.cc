// Differential harness: one source, compiled against Debian's MuJoCo 2.2.2 (harness-ref) and
// against rujoco (harness-ours).
//
//   harness-ref  record  MODEL DIR   reference run: model, trajectory, states, all checks -> DIR/ref
//   harness-ours replay  MODEL DIR   our run: the same checks at the reference's states -> DIR/ours
//   (record/replay MODEL DIR --model-only: the compiled model only; --groups a,b: those check
//   groups only, plus forward, which the others read: trajectories beyond the reference's
//   (ours, and its perturbed one for the noise floor) only with traj; --disable FLAGS: or FLAGS into
//   opt.disableflags of every model, e.g. 3 = constraints and contacts off; record --states N:
//   N states along the trajectory instead of 50, for large models, with --states-above NV: only
//   for models above nv NV; --max-nv NV: models above nv NV get their compiled model only)
//   harness-ref  compare DIR [-v] [--groups a,b]   worst relative error per quantity, exit 1 on
//                                    any failure (all groups, or the listed ones)
//
// Each check group runs in its own child process, so that an unimplemented function (mju_error)
// or a crash fails that group only, with the reason in DIR/<side>/<group>.status.
// State checks of our library run on the reference's compiled model copied into plain memory
// ("transplant"), so that physics is tested independently of our XML compiler; the trajectory
// check uses our own mj_loadXML (falling back to the transplant only if it fails, noted).

#include <dlfcn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <string>

#include <mujoco/mujoco.h>

#include "binfile.h"
#include "compare.h"
#include "dump.h"
#include "scenario.h"
#include "../wait_child.h"

namespace {

std::string g_status;  // status file of the running check group
int g_disable = 0;     // --disable: flags or-ed into opt.disableflags of every model run
int g_state_every = kStateEvery;  // --states N: a state every kSteps / N steps
int g_states_above = -1;          // --states-above NV: --states applies above nv NV only
int g_max_nv = -1;                // --max-nv NV: the compiled model only above nv NV

void write_status(const std::string& path, const std::string& text) {
  std::string line = text;  // one line: messages may hold newlines
  for (char& c : line) {
    if (c == '\n' || c == '\r') c = ' ';
  }
  FILE* fp = std::fopen(path.c_str(), "w");
  if (fp) {
    std::fprintf(fp, "%s\n", line.c_str());
    std::fclose(fp);
  }
}

void on_error(const char* msg) {
  write_status(g_status, std::string("mju_error: ") + msg);
  _exit(3);
}

// Prints the first few warnings of a check group (the data's warning counters are compared).
void on_warning(const char* msg) {
  static int count = 0;
  if (count < 3) std::fprintf(stderr, "mju_warning: %s\n", msg);
  if (count == 3) std::fprintf(stderr, "mju_warning: (further warnings not shown)\n");
  count++;
}

// Runs fn ("" = success, else a failure message) in a child process with a time limit.
bool isolated(const std::string& status, const std::function<std::string()>& fn, int seconds) {
  std::remove(status.c_str());
  std::fflush(stdout);
  std::fflush(stderr);
  pid_t pid = fork();
  if (pid == 0) {
    g_status = status;
    mju_user_error = on_error;
    mju_user_warning = on_warning;
    std::string r = fn();
    write_status(status, r.empty() ? "ok" : r);
    std::fflush(stdout);
    _exit(0);
  }
  int ws = 0;
  if (!wait_child(pid, seconds, &ws)) {
    write_status(status, "timed out after " + std::to_string(seconds) + " s");
    return false;
  }
  if (WIFSIGNALED(ws)) {
    write_status(status, std::string("crashed: signal ") + std::to_string(WTERMSIG(ws)) + " (" +
                             strsignal(WTERMSIG(ws)) + ")");
  } else if (WEXITSTATUS(ws) != 0 && read_status(status).rfind("mju_error", 0) != 0) {
    write_status(status, "exited with code " + std::to_string(WEXITSTATUS(ws)));
  }
  return read_status(status) == "ok";
}

mjModel* load(const char* path, std::string& error) {
  char err[1000] = "";
  mjModel* m = mj_loadXML(path, nullptr, err, sizeof err);
  if (!m) error = std::string("mj_loadXML failed: ") + err;
  else m->opt.disableflags |= g_disable;
  return m;
}

std::string saved(const Writer& w, const std::string& path) {
  return w.save(path) ? "" : "cannot write " + path;
}

const int kSeconds = 120;

// Is the check group selected by the comma-separated list (empty: all)? "forward" always runs:
// other groups read the reference's forward results.
bool selected(const std::string& only, const std::string& group) {
  return only.empty() || group == "forward" || group == "noise" ||
         ("," + only + ",").find("," + group + ",") != std::string::npos;
}

int record(const char* model, const std::string& dir, bool model_only, const std::string& only) {
  std::string out = dir + "/ref/";
  // one load, shared with every child: each runs on its own copy of the parent's memory
  // (an mju_error while loading ends the run with the model's status)
  std::string load_error;
  g_status = out + "model.status";
  mju_user_error = on_error;
  mju_user_warning = on_warning;
  mjModel* shared = load(model, load_error);
  mju_user_error = nullptr;
  mju_user_warning = nullptr;
  bool ok = isolated(out + "model.status", [&]() -> std::string {
    if (!shared) return load_error;
    Writer w;
    dump_model(shared, w);
    return saved(w, out + "model.bin");
  }, kSeconds);
  if (!shared) {
    // the groups fail as the load did, without a run each
    for (const char* g : {"traj", "trajnoise"}) write_status(out + g + ".status", load_error);
    for (const auto& gc : state_checks()) write_status(out + gc.first + ".status", load_error);
    write_status(out + "noise.status", load_error);
    return 1;
  }
  if (model_only || (g_max_nv >= 0 && shared->nv > g_max_nv)) return ok ? 0 : 1;
  if (g_states_above >= 0 && shared->nv <= g_states_above) g_state_every = kStateEvery;
  ok = isolated(out + "traj.status", [&]() -> std::string {
    mjModel* m = shared;
    mjData* d = mj_makeData(m);
    Writer traj, states;
    run_trajectory(m, d, traj, &states, false, g_state_every);
    std::string r = saved(states, dir + "/states.bin");
    return r.empty() ? saved(traj, out + "traj.bin") : r;
  }, kSeconds) && ok;
  // the reference's noise floors: a perturbed trajectory (for the traj group only), and
  // forward at perturbed states
  std::vector<std::pair<std::string, Check>> checks = state_checks();
  checks.push_back({"noise", check_noise});
  if (selected(only, "traj")) {
    isolated(out + "trajnoise.status", [&]() -> std::string {
      mjModel* m = shared;
      mjData* d = mj_makeData(m);
      Writer traj;
      run_trajectory(m, d, traj, nullptr, true);
      return saved(traj, out + "trajnoise.bin");
    }, kSeconds);
  }
  // read once here and shared with every group's child (forward.bin once the forward group,
  // which runs first, has written it)
  Reader states, post;
  bool have_states = false, have_post = false;
  for (const auto& [group, check] : checks) {
    if (!selected(only, group)) continue;
    if (!have_states) have_states = states.load(dir + "/states.bin");
    if (!have_post && group != "forward") have_post = post.load(out + "forward.bin");
    ok = isolated(out + group + ".status", [&, group = group, check = check]() -> std::string {
      mjModel* m = shared;
      mjData* d = mj_makeData(m);
      if (!have_states) return "no states.bin";
      const Rec* n = states.get("nstate");
      Inputs in{&states, &post, n ? n->i()[0] : 0};
      Writer w;
      check(m, d, in, w);
      return saved(w, out + group + ".bin");
    }, kSeconds) && ok;
  }
  return ok ? 0 : 1;
}

int replay(const char* model, const std::string& dir, bool model_only, const std::string& only) {
  std::string out = dir + "/ours/";
  std::string ref = dir + "/ref/";
  std::remove((out + "traj.note").c_str());
  isolated(out + "model.status", [&]() -> std::string {
    std::string e;
    mjModel* m = load(model, e);
    if (!m) return e;
    Writer w;
    dump_model(m, w);
    return saved(w, out + "model.bin");
  }, kSeconds);
  if (model_only) return 0;
  Reader refmodel;
  bool have_ref = refmodel.load(ref + "model.bin");
  const Rec* nv = have_ref ? refmodel.get("size.nv") : nullptr;
  if (g_max_nv >= 0 && nv && nv->i()[0] > g_max_nv) return 0;
  // our loader's result decides the trajectory's model (a failing mj_loadXML cannot return)
  bool loads = read_status(out + "model.status") == "ok";
  // our trajectory: compared in the traj group only
  if (selected(only, "traj")) isolated(out + "traj.status", [&]() -> std::string {
    std::string e;
    mjModel* m = nullptr;
    if (loads) {
      m = load(model, e);
      if (!m) return e;
    } else {
      if (!have_ref) return "no reference model.bin";
      std::string why = read_status(out + "model.status");
      write_status(out + "traj.note", "on the transplanted reference model, as loading failed (" + why + ")");
      m = transplant_model(refmodel);
      m->opt.disableflags |= g_disable;
    }
    mjData* d = mj_makeData(m);
    if (!d) return "mj_makeData returned NULL";
    Writer traj;
    run_trajectory(m, d, traj, nullptr);
    return saved(traj, out + "traj.bin");
  }, kSeconds);
  // read once here and shared with every group's child (the forward group needs no results)
  Reader states, post;
  bool have_states = false, have_post = false;
  for (const auto& [group, check] : state_checks()) {
    if (!selected(only, group)) continue;
    if (!have_states) have_states = states.load(dir + "/states.bin");
    if (!have_post && group != "forward") have_post = post.load(ref + "forward.bin");
    isolated(out + group + ".status", [&, group = group, check = check]() -> std::string {
      if (!have_ref) return "no reference model.bin";
      mjModel* m = transplant_model(refmodel);
      m->opt.disableflags |= g_disable;
      mjData* d = needs_data(group) ? mj_makeData(m) : nullptr;
      if (needs_data(group) && !d) return "mj_makeData returned NULL";
      if (!have_states) return "no states.bin";
      const Rec* n = states.get("nstate");
      Inputs in{&states, &post, n ? n->i()[0] : 0};
      Writer w;
      check(m, d, in, w);
      return saved(w, out + group + ".bin");
    }, kSeconds);
  }
  return 0;
}

int compare(const std::string& dir, bool verbose, const std::string& only) {
  std::vector<std::string> groups;
  std::vector<std::string> all = {"model", "traj"};
  for (const auto& gc : state_checks()) all.push_back(gc.first);
  for (const std::string& g : all) {
    if (only.empty() || ("," + only + ",").find("," + g + ",") != std::string::npos) groups.push_back(g);
  }
  int npass = 0;
  double worst = 0, residual = 0;
  Floors floors = noise_floors(dir + "/ref/forward.bin", dir + "/ref/noise.bin");
  bool traj = selected(only, "traj");
  Floors traj_floors;
  if (traj) traj_floors = noise_floors(dir + "/ref/traj.bin", dir + "/ref/trajnoise.bin");
  bool dynamic = false;
  for (const std::string& g : groups) dynamic = dynamic || !static_group(g);
  if (dynamic) {
    std::printf("  noise floor of the reference (state perturbed by %.0e): forward %.2e", kNoise,
                floors.model);
    if (traj) std::printf(", trajectory %.2e", traj_floors.model);
    std::printf("\n");
  }
  if (dynamic && verbose) {
    std::printf("    forward floor at %s\n", floors.at.c_str());
    if (traj) std::printf("    trajectory floor at %s\n", traj_floors.at.c_str());
  }
  for (const std::string& g : groups) {
    double gw;
    const Floors* f = static_group(g) ? nullptr : g == "traj" ? &traj_floors : &floors;
    bool ok = compare_group(dir, g, tolerance(g), verbose, &gw, f);
    if (g == "traj") {
      std::string note = read_status(dir + "/ours/traj.note");
      if (note.rfind("no result", 0) != 0) std::printf("  %-16s note  %s\n", "traj", note.c_str());
    }
    npass += ok;
    // consistency holds self-check residuals, not differences between the libraries
    double& w = g == "consistency" ? residual : worst;
    if (!(gw <= w)) w = gw;
  }
  std::printf("  %d of %zu check groups pass; worst relative error %.2e", npass, groups.size(), worst);
  if (residual > 0) std::printf(" (self-check residuals up to %.2e)", residual);
  std::printf("\n");
  return npass == (int)groups.size() ? 0 : 1;
}

// The library this binary runs against must be the one it was built for (LD_LIBRARY_PATH
// could swap them: both carry the SONAME libmujoco.so.2.2.2).
bool right_library() {
  Dl_info info;
  if (!dladdr((void*)&mj_step, &info) || !info.dli_fname) return true;
  char real[4096];
  std::string path = realpath(info.dli_fname, real) ? real : info.dli_fname;
  bool is_ref = path.rfind("/usr/lib/", 0) == 0;
#ifdef RJ_OURS
  bool want_ref = false;
#else
  bool want_ref = true;
#endif
  if (is_ref != want_ref) {
    std::fprintf(stderr, "harness built for %s loaded %s: check LD_LIBRARY_PATH\n",
                 want_ref ? "Debian's libmujoco" : "rujoco", path.c_str());
  }
  return is_ref == want_ref;
}

int usage() {
  std::fprintf(stderr,
               "usage: harness record|replay MODEL DIR [--model-only] [--groups g1,g2,...] [--disable FLAGS] [--states N [--states-above NV]] [--max-nv NV] | "
               "harness compare DIR [-v] [--groups g1,g2,...]\n");
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) return usage();
  if (!right_library()) return 4;
  std::string mode = argv[1];
  if (mode == "compare") {
    bool verbose = false;
    std::string only;
    for (int i = 3; i < argc; i++) {
      if (!std::strcmp(argv[i], "-v")) verbose = true;
      else if (!std::strcmp(argv[i], "--groups") && i + 1 < argc) only = argv[++i];
      else return usage();
    }
    return compare(argv[2], verbose, only);
  }
  if (argc < 4) return usage();
  std::string dir = argv[3];
  mkdir(dir.c_str(), 0755);
  mkdir((dir + "/ref").c_str(), 0755);
  mkdir((dir + "/ours").c_str(), 0755);
  bool model_only = false;
  std::string only;
  for (int i = 4; i < argc; i++) {
    if (!std::strcmp(argv[i], "--model-only")) model_only = true;
    else if (!std::strcmp(argv[i], "--groups") && i + 1 < argc) only = argv[++i];
    else if (!std::strcmp(argv[i], "--disable") && i + 1 < argc) g_disable = std::atoi(argv[++i]);
    else if (!std::strcmp(argv[i], "--states") && i + 1 < argc) {
      int n = std::atoi(argv[++i]);
      if (n < 1 || n > kSteps) return usage();
      g_state_every = kSteps / n;
    }
    else if (!std::strcmp(argv[i], "--states-above") && i + 1 < argc) g_states_above = std::atoi(argv[++i]);
    else if (!std::strcmp(argv[i], "--max-nv") && i + 1 < argc) g_max_nv = std::atoi(argv[++i]);
    else return usage();
  }
  if (mode == "record") return record(argv[2], dir, model_only, only);
  if (mode == "replay") return replay(argv[2], dir, model_only, only);
  return usage();
}
