// Comparator: the reference's records against ours, worst relative error per quantity.
//
// Relative error of two numbers a (reference) and b (ours):
//     err(a, b) = |a - b| / max(1, |a|, |b|)
// i.e. relative for magnitudes above 1 and absolute below (floor 1). Both NaN: 0; one NaN or
// infinite where the other is not: inf. Quaternion records ('q') take the better of q and -q.
// Integers, bytes and strings must match exactly (else inf). Self-check residuals ('s') report
// the larger of the two sides' residuals. A quantity's error is the maximum over its elements
// and instances (states, objects); it passes when that is <= the group's tolerance.

#pragma once

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include "binfile.h"

inline double rel_err(double a, double b) {
  if (std::isnan(a) || std::isnan(b)) return (std::isnan(a) && std::isnan(b)) ? 0 : INFINITY;
  if (a == b) return 0;
  if (std::isinf(a) || std::isinf(b)) return INFINITY;
  return std::fabs(a - b) / std::max({1.0, std::fabs(a), std::fabs(b)});
}

struct Worst {
  double err = 0;
  std::string where;
  size_t n = 0;  // elements compared
};

// Error of one record pair; where = element index and values at the worst element.
inline double rec_err(const Rec& a, const Rec& b, std::string& where) {
  char buf[160];
  if (a.type != b.type || a.bytes.size() != b.bytes.size()) {
    std::snprintf(buf, sizeof buf, "type/size: ref %c/%zu ours %c/%zu", a.type, a.count(), b.type,
                  b.count());
    where = buf;
    return INFINITY;
  }
  double worst = 0;
  size_t at = 0, n = a.count();
  auto note = [&](size_t i, double e) {
    if (e > worst || (std::isnan(e) && !std::isnan(worst))) {
      worst = e;
      at = i;
    }
  };
  switch (a.type) {
    case 'd':
      for (size_t i = 0; i < n; i++) note(i, rel_err(a.d()[i], b.d()[i]));
      break;
    case 'f':
      for (size_t i = 0; i < n; i++) note(i, rel_err(a.f()[i], b.f()[i]));
      break;
    case 's':
      for (size_t i = 0; i < n; i++) note(i, std::max(a.d()[i], b.d()[i]));
      break;
    case 'q':
      for (size_t i = 0; i + 3 < n; i += 4) {
        double plus = 0, minus = 0;
        for (int j = 0; j < 4; j++) {
          plus = std::max(plus, rel_err(a.d()[i + j], b.d()[i + j]));
          minus = std::max(minus, rel_err(a.d()[i + j], -b.d()[i + j]));
        }
        note(i, std::min(plus, minus));
      }
      break;
    case 'i':
      for (size_t i = 0; i < n; i++) note(i, a.i()[i] == b.i()[i] ? 0 : INFINITY);
      break;
    default:
      for (size_t i = 0; i < n; i++) note(i, a.bytes[i] == b.bytes[i] ? 0 : INFINITY);
  }
  if (worst > 0) {
    if (a.type == 'd' || a.type == 'q' || a.type == 's')
      std::snprintf(buf, sizeof buf, "[%zu] ref %.17g ours %.17g", at, a.d()[at], b.d()[at]);
    else if (a.type == 'f')
      std::snprintf(buf, sizeof buf, "[%zu] ref %.9g ours %.9g", at, a.f()[at], b.f()[at]);
    else if (a.type == 'i')
      std::snprintf(buf, sizeof buf, "[%zu] ref %d ours %d", at, a.i()[at], b.i()[at]);
    else if (a.type == 'c')
      std::snprintf(buf, sizeof buf, "ref \"%.60s\" ours \"%.60s\"",
                    std::string(a.bytes.begin(), a.bytes.end()).c_str(),
                    std::string(b.bytes.begin(), b.bytes.end()).c_str());
    else
      std::snprintf(buf, sizeof buf, "[%zu] ref %d ours %d", at, a.bytes[at], b.bytes[at]);
    where = buf;
  }
  return worst;
}

inline std::string fmt(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.0e", x);
  return buf;
}

inline std::string read_status(const std::string& path) {
  FILE* fp = std::fopen(path.c_str(), "r");
  if (!fp) return "no result (not run)";
  char buf[1200] = {0};
  size_t n = std::fread(buf, 1, sizeof buf - 1, fp);
  std::fclose(fp);
  std::string s(buf, n);
  while (!s.empty() && (s.back() == '\n' || s.back() == ' ')) s.pop_back();
  return s.empty() ? "no result (empty status)" : s;
}

// How far two runs of the reference differ, per quantity: the worst relative error over the
// real-valued records both hold with the same size (records of a changed contact or
// constraint set are left out; their effect shows in the others). Empty if a file is missing.
struct Floors {
  std::map<std::string, double> per;  // quantity -> floor
  double model = 0;                   // worst over all but the solver's convergence statistics
  std::string at;                     // where the model floor is reached
  // 1000 times the floor of a quantity (the model's floor for quantities not in the runs)
  double allowance(const std::string& q) const {
    auto it = per.find(q);
    return 1000 * (it == per.end() ? model : it->second);
  }
};

inline Floors noise_floors(const std::string& a_path, const std::string& b_path) {
  Floors f;
  IndexedReader a, b;
  if (!a.open(a_path) || !b.open(b_path)) return f;
  Rec ra, rb;
  for (const std::string& name : a.names()) {
    if (!a.fetch(name, ra)) continue;
    if (ra.type != 'd' && ra.type != 'q') continue;
    if (!b.fetch(name, rb) || rb.bytes.size() != ra.bytes.size()) continue;
    std::string where, q = ra.name.substr(0, ra.name.find('#'));
    double e = rec_err(ra, rb, where);
    if (!std::isfinite(e)) continue;
    double& pq = f.per[q];
    pq = std::max(pq, e);
    if (q.rfind("solver.", 0) != 0 && e > f.model) {
      f.model = e;
      f.at = ra.name + " " + where;
    }
  }
  return f;
}

// Compares one check group; prints per-quantity lines (all, or failing only). Returns pass.
// tol: the group's own tolerance; floors (optional) raise it per quantity to 1000 times the
// reference's noise floor.
inline bool compare_group(const std::string& dir, const std::string& group, double tol,
                          bool verbose, double* group_worst, const Floors* floors = nullptr) {
  std::string ref_status = read_status(dir + "/ref/" + group + ".status");
  std::string our_status = read_status(dir + "/ours/" + group + ".status");
  *group_worst = INFINITY;
  if (ref_status != "ok") {
    std::printf("  %-16s FAIL  reference run: %s\n", group.c_str(), ref_status.c_str());
    return false;
  }
  if (our_status != "ok") {
    std::printf("  %-16s FAIL  %s\n", group.c_str(), our_status.c_str());
    return false;
  }
  // one record of each side in memory at a time: result files can exceed memory
  IndexedReader ref, ours;
  if (!ref.open(dir + "/ref/" + group + ".bin") || !ours.open(dir + "/ours/" + group + ".bin")) {
    std::printf("  %-16s FAIL  unreadable result file\n", group.c_str());
    return false;
  }
  std::vector<std::string> order;
  std::map<std::string, Worst> per;
  Rec a, ob;
  for (const std::string& name : ref.names()) {
    if (!ref.fetch(name, a)) {
      std::printf("  %-16s FAIL  unreadable record %s\n", group.c_str(), name.c_str());
      return false;
    }
    if (a.type == 'r' || a.type == 'o') continue;
    std::string q = a.name.substr(0, a.name.find('#'));
    if (!per.count(q)) order.push_back(q);
    Worst& w = per[q];
    const Rec* b = ours.fetch(name, ob) ? &ob : nullptr;
    std::string where;
    double e = b ? rec_err(a, *b, where) : INFINITY;
    if (!b) where = "missing in ours";
    w.n += a.count();
    if (e > w.err || (std::isnan(e) && !std::isnan(w.err)) || (w.where.empty() && e > 0)) {
      w.err = e;
      w.where = a.name + " " + where;
    }
  }
  bool pass = true;
  double gw = 0;
  std::string gq;
  int nfail = 0;
  for (const std::string& q : order) {
    const Worst& w = per[q];
    double qtol = floors ? std::max(tol, floors->allowance(q)) : tol;
    bool ok = w.err <= qtol;
    if (!ok) nfail++;
    pass = pass && ok;
    if (!(w.err <= gw)) {
      gw = w.err;
      gq = q;
    }
    if (verbose || !ok)
      std::printf("  %-16s %-6s %-28s %9.2e  (n=%zu%s)%s%s\n", group.c_str(), ok ? "ok" : "FAIL",
                  q.c_str(), w.err, w.n, qtol > tol ? (", tol " + fmt(qtol)).c_str() : "",
                  w.err > 0 ? "  worst at " : "", w.err > 0 ? w.where.c_str() : "");
  }
  *group_worst = gw;
  std::printf("  %-16s %-6s %zu quantities, %d failing, worst %.2e%s%s (tol %.0e%s)\n",
              group.c_str(), pass ? "PASS" : "FAIL", order.size(), nfail, gw, gq.empty() ? "" : " in ",
              gq.c_str(), tol, floors && floors->model > 0 ? ", or 1000x noise floor" : "");
  return pass;
}
