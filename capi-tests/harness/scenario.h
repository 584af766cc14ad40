// The scenario both libraries run: a driven trajectory, and the checks evaluated at its states.
// Every check is a function (model, data, inputs) -> records, identical for both libraries.

#pragma once

#include <cmath>
#include <cstdlib>
#include <functional>
#include <string>
#include <vector>

#include <Eigen/Dense>
#include <mujoco/mujoco.h>

#include "binfile.h"
#include "dump.h"

constexpr int kSteps = 1000;      // trajectory length
constexpr int kStateEvery = 20;   // a state every 20 steps: 50 states
constexpr int kTrajEvery = 10;    // trajectory records every 10 steps
constexpr double kDt = 0.01;      // time step of the integratePos/differentiatePos checks
constexpr double kNoise = 1e-14;  // relative state perturbation that measures the noise floor

inline std::string I(int a) { return std::to_string(a); }
inline std::string I(int a, int b) { return std::to_string(a) + "." + std::to_string(b); }

// Deterministic inputs at time t: controls, applied forces, mocap motion.
inline void drive(const mjModel* m, mjData* d, const std::vector<mjtNum>& mocap0) {
  mjtNum t = d->time;
  for (int i = 0; i < m->nu; i++) {
    mjtNum s = std::sin(2 * mjPI * (0.5 + 0.3 * i) * t + i);
    if (m->actuator_ctrllimited[i]) {
      mjtNum lo = m->actuator_ctrlrange[2 * i], hi = m->actuator_ctrlrange[2 * i + 1];
      d->ctrl[i] = lo + (hi - lo) * (0.5 + 0.4 * s);
    } else {
      d->ctrl[i] = 0.5 * s;
    }
  }
  for (int i = 0; i < m->nv; i++) d->qfrc_applied[i] = 0.02 * std::sin(1.3 * t + i);
  for (int b = 1; b < m->nbody; b++) {
    d->xfrc_applied[6 * b + 0] = 0.05 * std::cos(t + b);
    d->xfrc_applied[6 * b + 5] = 0.01 * std::sin(2 * t + b);
  }
  for (int j = 0; j < m->nmocap; j++) {
    d->mocap_pos[3 * j + 0] = mocap0[3 * j + 0] + 0.1 * std::sin(t);
    d->mocap_pos[3 * j + 1] = mocap0[3 * j + 1] + 0.1 * std::cos(t);
    d->mocap_pos[3 * j + 2] = mocap0[3 * j + 2];
    mjtNum q[4] = {std::cos(t / 4), 0, 0, std::sin(t / 4)};
    for (int k = 0; k < 4; k++) d->mocap_quat[4 * j + k] = q[k];
  }
}

// Sensor noise draws from C's rand(): both sides start from the same seed, however the
// model was made (the reference's mj_loadXML reseeds it, a transplanted model does not).
inline void seed_noise() { std::srand(1); }

inline void reset(const mjModel* m, mjData* d) {
  seed_noise();
  mj_resetData(m, d);
  if (m->nkey > 0) mj_resetDataKeyframe(m, d, 0);
}

// Moves the state (qpos, qvel, act) by kNoise relative (absolute below 1, as the comparator),
// alternating signs: the reference's own response is the noise floor a comparison cannot beat.
inline void perturb(const mjModel* m, mjData* d) {
  auto scale = [](mjtNum* x, int n) {
    for (int i = 0; i < n; i++) x[i] += (i % 2 ? -kNoise : kNoise) * std::max(1.0, std::fabs(x[i]));
  };
  scale(d->qpos, m->nq);
  scale(d->qvel, m->nv);
  scale(d->act, m->na);
}

// The 1000-step trajectory: records qpos/qvel/act/qacc_warmstart/time, and optionally the states.
// perturbed: start from the perturbed initial state (the reference's trajectory noise floor);
// a state every state_every steps.
inline void run_trajectory(const mjModel* m, mjData* d, Writer& traj, Writer* states,
                           bool perturbed = false, int state_every = kStateEvery) {
  reset(m, d);
  if (perturbed) perturb(m, d);
  std::vector<mjtNum> mocap0(d->mocap_pos, d->mocap_pos + 3 * m->nmocap);
  int nstate = 0;
  for (int step = 0; step < kSteps; step++) {
    drive(m, d, mocap0);
    if (states && step % state_every == 0) dump_state(m, d, *states, I(nstate++));
    mj_step(m, d);
    if (step % kTrajEvery == kTrajEvery - 1) {
      std::string k = I(step + 1);
      traj.d("traj.time#" + k, &d->time, 1);
      traj.d("traj.qpos#" + k, d->qpos, m->nq);
      traj.d("traj.qvel#" + k, d->qvel, m->nv);
      traj.d("traj.act#" + k, d->act, m->na);
      traj.d("traj.qacc_warmstart#" + k, d->qacc_warmstart, m->nv);
      traj.d("traj.sensordata#" + k, d->sensordata, m->nsensordata);
    }
  }
  // the stack's high-water mark over the whole trajectory (2.2.2's scratch sizes and nesting)
  traj.i1("traj.maxuse_stack", d->maxuse_stack);
  if (states) states->i1("nstate", nstate);
}

// Inputs of a check at state k: the state, and the reference's mj_forward results there.
struct Inputs {
  const Reader* states;
  const Reader* post;  // forward.bin of the reference
  int nstate;
};

using Check = std::function<void(const mjModel*, mjData*, const Inputs&, Writer&)>;

// Prepares d at state k: reset, state copied in, and (post) the reference forward results.
inline void at_state(const mjModel* m, mjData* d, const Inputs& in, int k, bool post) {
  seed_noise();
  mj_resetData(m, d);
  load_state(m, d, *in.states, I(k));
  if (post) load_data(m, d, *in.post, I(k));
}

inline void check_forward(const mjModel* m, mjData* d, const Inputs& in, Writer& w) {
  for (int k = 0; k < in.nstate; k++) {
    at_state(m, d, in, k, false);
    mj_forward(m, d);
    dump_data(m, d, w, I(k));
  }
}

// mj_forward at each state perturbed by kNoise: recorded by the reference only, against its
// "forward" results it gives the noise floor of the state checks.
inline void check_noise(const mjModel* m, mjData* d, const Inputs& in, Writer& w) {
  for (int k = 0; k < in.nstate; k++) {
    at_state(m, d, in, k, false);
    perturb(m, d);
    mj_forward(m, d);
    dump_data(m, d, w, I(k), 100000);  // large dense matrices take the model's floor
  }
}

// One mj_step from each state: localizes integrator differences the trajectory accumulates.
inline void check_step(const mjModel* m, mjData* d, const Inputs& in, Writer& w) {
  for (int k = 0; k < in.nstate; k++) {
    at_state(m, d, in, k, false);
    mj_step(m, d);
    std::string i = I(k);
    w.d("time#" + i, &d->time, 1);
    w.d("qpos#" + i, d->qpos, m->nq);
    w.d("qvel#" + i, d->qvel, m->nv);
    w.d("act#" + i, d->act, m->na);
    w.d("qacc#" + i, d->qacc, m->nv);
    w.d("qacc_warmstart#" + i, d->qacc_warmstart, m->nv);
    w.d("sensordata#" + i, d->sensordata, m->nsensordata);
    w.d("solver_fwdinv#" + i, d->solver_fwdinv, 2);  // mjENBL_FWDINV
    w.d("energy#" + i, d->energy, 2);
    // what a renderer reads after the step
    w.d("cam_xpos#" + i, d->cam_xpos, 3 * m->ncam);
    w.d("cam_xmat#" + i, d->cam_xmat, 9 * m->ncam);
    w.d("light_xpos#" + i, d->light_xpos, 3 * m->nlight);
    w.d("light_xdir#" + i, d->light_xdir, 3 * m->nlight);
  }
}

inline void test_point(const mjData* d, int body, mjtNum* point) {
  const mjtNum off[3] = {0.1, -0.2, 0.3};
  for (int j = 0; j < 3; j++) point[j] = d->xpos[3 * body + j] + off[j];
}

// One jacobian function over every object it takes, at every state.
inline Check check_jac(const std::string& fn) {
  return [fn](const mjModel* m, mjData* d, const Inputs& in, Writer& w) {
    std::vector<mjtNum> a(3 * m->nv), b(3 * m->nv);
    int n = fn == "jacSite" ? m->nsite : fn == "jacGeom" ? m->ngeom : m->nbody;
    for (int k = 0; k < in.nstate; k++) {
      at_state(m, d, in, k, true);
      for (int i = 0; i < n; i++) {
        // a unit axis, normalized here so that only the function under test is called
        mjtNum point[3] = {0, 0, 0}, axis[3] = {0.3 / std::sqrt(0.98), 0.5 / std::sqrt(0.98),
                                                -0.8 / std::sqrt(0.98)};
        if (fn == "jac" || fn == "jacPointAxis") test_point(d, i, point);
        if (fn == "jacSite") mj_jacSite(m, d, a.data(), b.data(), i);
        if (fn == "jacBody") mj_jacBody(m, d, a.data(), b.data(), i);
        if (fn == "jacBodyCom") mj_jacBodyCom(m, d, a.data(), b.data(), i);
        if (fn == "jacGeom") mj_jacGeom(m, d, a.data(), b.data(), i);
        if (fn == "jac") mj_jac(m, d, a.data(), b.data(), point, i);
        if (fn == "jacPointAxis") mj_jacPointAxis(m, d, a.data(), b.data(), point, axis, i);
        w.d(fn + ".first#" + I(k, i), a.data(), a.size());
        w.d(fn + ".second#" + I(k, i), b.data(), b.size());
      }
    }
  };
}

inline std::vector<mjtNum> test_vector(int n, int k) {
  std::vector<mjtNum> v(n);
  for (int i = 0; i < n; i++) v[i] = std::sin(1.0 + i + 0.1 * k);
  return v;
}

inline void check_fullM(const mjModel* m, mjData* d, const Inputs& in, Writer& w) {
  std::vector<mjtNum> M(m->nv * m->nv);
  for (int k = 0; k < in.nstate; k++) {
    at_state(m, d, in, k, true);
    mj_fullM(m, M.data(), d->qM);
    w.d("fullM#" + I(k), M.data(), M.size());
  }
}

inline void check_mulM(const mjModel* m, mjData* d, const Inputs& in, Writer& w) {
  std::vector<mjtNum> res(m->nv);
  for (int k = 0; k < in.nstate; k++) {
    at_state(m, d, in, k, true);
    std::vector<mjtNum> v = test_vector(m->nv, k);
    mj_mulM(m, d, res.data(), v.data());
    w.d("mulM#" + I(k), res.data(), m->nv);
  }
}

inline void check_mulM2(const mjModel* m, mjData* d, const Inputs& in, Writer& w) {
  std::vector<mjtNum> res(m->nv);
  for (int k = 0; k < in.nstate; k++) {
    at_state(m, d, in, k, true);
    std::vector<mjtNum> v = test_vector(m->nv, k);
    mj_mulM2(m, d, res.data(), v.data());
    w.d("mulM2#" + I(k), res.data(), m->nv);
  }
}

inline void check_solveM(const mjModel* m, mjData* d, const Inputs& in, Writer& w) {
  std::vector<mjtNum> res(m->nv);
  for (int k = 0; k < in.nstate; k++) {
    at_state(m, d, in, k, true);
    std::vector<mjtNum> v = test_vector(m->nv, k);
    mj_solveM(m, d, res.data(), v.data(), 1);
    w.d("solveM#" + I(k), res.data(), m->nv);
  }
}

// Self-consistency with Eigen: fullM symmetric (and positive definite as in the reference),
// mulM = fullM * v, fullM * solveM(v) = v. Residuals relative to max(1, |M| |v|).
inline void check_consistency(const mjModel* m, mjData* d, const Inputs& in, Writer& w) {
  using Mat = Eigen::Matrix<mjtNum, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
  using Vec = Eigen::Matrix<mjtNum, Eigen::Dynamic, 1>;
  int nv = m->nv;
  for (int k = 0; k < in.nstate; k++) {
    at_state(m, d, in, k, true);
    Mat M(nv, nv);
    mj_fullM(m, M.data(), d->qM);
    Vec v = Eigen::Map<Vec>(test_vector(nv, k).data(), nv);
    Vec mv(nv), x(nv);
    mj_mulM(m, d, mv.data(), v.data());
    mj_solveM(m, d, x.data(), v.data(), 1);
    double scale = std::max(1.0, M.norm() * std::max(1.0, v.norm()));
    bool spd = Eigen::LLT<Mat>(M).info() == Eigen::Success;
    w.s1("symmetry(fullM)#" + I(k), (M - M.transpose()).norm() / scale);
    w.i1("spd(fullM)#" + I(k), spd);  // compared exactly: some models have a singular M
    w.s1("mulM-fullM*v#" + I(k), (M * v - mv).norm() / scale);
    if (spd) w.s1("fullM*solveM(v)-v#" + I(k), (M * x - v).norm() / scale);
  }
}

// The state's positions and velocities, read directly (no mjData needed).
inline std::vector<mjtNum> state_array(const Inputs& in, const char* name, int k) {
  const Rec* r = in.states->get(std::string(name) + "#" + I(k));
  return r ? std::vector<mjtNum>(r->d(), r->d() + r->count()) : std::vector<mjtNum>();
}

inline void check_integratePos(const mjModel* m, mjData*, const Inputs& in, Writer& w) {
  for (int k = 0; k < in.nstate; k++) {
    std::vector<mjtNum> q = state_array(in, "qpos", k), v = state_array(in, "qvel", k);
    mj_integratePos(m, q.data(), v.data(), kDt);
    w.d("integratePos#" + I(k), q.data(), m->nq);
  }
}

inline void check_differentiatePos(const mjModel* m, mjData*, const Inputs& in, Writer& w) {
  std::vector<mjtNum> v(m->nv);
  for (int k = 0; k + 1 < in.nstate; k++) {
    std::vector<mjtNum> q0 = state_array(in, "qpos", k), q1 = state_array(in, "qpos", k + 1);
    mj_differentiatePos(m, v.data(), kDt, q0.data(), q1.data());
    w.d("differentiatePos#" + I(k), v.data(), m->nv);
  }
}

// mj_id2name for every named object type and id, mj_name2id back, and names that share a start,
// unknown and empty names.
inline void check_names(const mjModel* m, mjData*, const Inputs&, Writer& w) {
  const int types[][2] = {
      {mjOBJ_BODY, m->nbody},       {mjOBJ_JOINT, m->njnt},        {mjOBJ_GEOM, m->ngeom},
      {mjOBJ_SITE, m->nsite},       {mjOBJ_CAMERA, m->ncam},       {mjOBJ_LIGHT, m->nlight},
      {mjOBJ_MESH, m->nmesh},       {mjOBJ_SKIN, m->nskin},        {mjOBJ_HFIELD, m->nhfield},
      {mjOBJ_TEXTURE, m->ntex},     {mjOBJ_MATERIAL, m->nmat},     {mjOBJ_PAIR, m->npair},
      {mjOBJ_EXCLUDE, m->nexclude}, {mjOBJ_EQUALITY, m->neq},      {mjOBJ_TENDON, m->ntendon},
      {mjOBJ_ACTUATOR, m->nu},      {mjOBJ_SENSOR, m->nsensor},    {mjOBJ_NUMERIC, m->nnumeric},
      {mjOBJ_TEXT, m->ntext},       {mjOBJ_TUPLE, m->ntuple},      {mjOBJ_KEY, m->nkey}};
  for (const auto& t : types) {
    for (int id = 0; id < t[1]; id++) {
      const char* name = mj_id2name(m, t[0], id);
      w.str("id2name#" + I(t[0], id), name);
      if (name && name[0]) {
        w.i1("name2id#" + I(t[0], id), mj_name2id(m, t[0], name));
        // the name without its last character, and with one more: names that share a start
        std::string s(name);
        std::string prefix = s.substr(0, s.size() - 1);
        w.i1("name2id(prefix)#" + I(t[0], id), mj_name2id(m, t[0], prefix.c_str()));
        w.i1("name2id(longer)#" + I(t[0], id), mj_name2id(m, t[0], (s + "x").c_str()));
      }
    }
    w.i1("name2id(unknown)#" + I(t[0]), mj_name2id(m, t[0], "no such name"));
    w.i1("name2id(empty)#" + I(t[0]), mj_name2id(m, t[0], ""));
  }
}

// Inverse dynamics at the reference's forward results: every mjData array after mj_inverse,
// then mj_inverseSkip from the velocity stage (no sensors) for a perturbed qacc.
inline void check_inverse(const mjModel* m, mjData* d, const Inputs& in, Writer& w) {
  for (int k = 0; k < in.nstate; k++) {
    at_state(m, d, in, k, true);
    mj_inverse(m, d);
    dump_data(m, d, w, I(k));
    std::vector<mjtNum> v = test_vector(m->nv, k);
    for (int i = 0; i < m->nv; i++) d->qacc[i] += v[i];
    mj_inverseSkip(m, d, mjSTAGE_VEL, 1);
    w.d("skip.qfrc_inverse#" + I(k), d->qfrc_inverse, m->nv);
    w.d("skip.qfrc_constraint#" + I(k), d->qfrc_constraint, m->nv);
  }
}

// The reference's contacts at state k (dump_contacts), which load_data leaves out.
inline void load_contacts(mjData* d, const Reader& r, const std::string& inst) {
  const size_t nreal = offsetof(mjContact, dim) / sizeof(mjtNum);
  for (int c = 0; c < d->ncon; c++) {
    mjContact* con = d->contact + c;
    std::string ci = inst + "." + std::to_string(c);
    r.copy("contact.real#" + ci, &con->dist, nreal * sizeof(mjtNum));
    r.copy("contact.int#" + ci, &con->dim, 5 * sizeof(int));
  }
}

// Post-solve quantities at the reference's forward results, contacts included:
// mj_contactForce, mj_subtreeVel, mj_rnePostConstraint, mj_objectVelocity /
// mj_objectAcceleration of every object with a frame, global and local, and mj_local2Global.
inline void check_objects(const mjModel* m, mjData* d, const Inputs& in, Writer& w) {
  const int types[][2] = {{mjOBJ_BODY, m->nbody}, {mjOBJ_XBODY, m->nbody}, {mjOBJ_GEOM, m->ngeom},
                          {mjOBJ_SITE, m->nsite}, {mjOBJ_CAMERA, m->ncam}};
  for (int k = 0; k < in.nstate; k++) {
    at_state(m, d, in, k, true);
    load_contacts(d, *in.post, I(k));
    for (int c = 0; c < d->ncon; c++) {
      mjtNum f[6];
      mj_contactForce(m, d, c, f);
      w.d("contactForce#" + I(k, c), f, 6);
    }
    mj_subtreeVel(m, d);
    mj_rnePostConstraint(m, d);
    std::string i = I(k);
    w.d("subtree_linvel#" + i, d->subtree_linvel, 3 * m->nbody);
    w.d("subtree_angmom#" + i, d->subtree_angmom, 3 * m->nbody);
    w.d("cacc#" + i, d->cacc, 6 * m->nbody);
    w.d("cfrc_int#" + i, d->cfrc_int, 6 * m->nbody);
    w.d("cfrc_ext#" + i, d->cfrc_ext, 6 * m->nbody);
    for (const auto& t : types) {
      for (int id = 0; id < t[1]; id++) {
        for (int local = 0; local < 2; local++) {
          mjtNum res[6];
          std::string j = I(k, t[0]) + "." + I(id, local);
          mj_objectVelocity(m, d, t[0], id, res, local);
          w.d("objectVelocity#" + j, res, 6);
          mj_objectAcceleration(m, d, t[0], id, res, local);
          w.d("objectAcceleration#" + j, res, 6);
        }
      }
    }
    // mj_local2Global of a point and orientation on each body, in each frame, with either
    // output alone (the other left as it was)
    const mjtNum pos[3] = {0.1, -0.2, 0.3}, quat[4] = {0.8, 0.2, -0.4, 0.4};
    for (int b = 0; b < m->nbody; b++) {
      for (int same = 0; same < 3; same++) {
        mjtNum xp[3] = {7, 7, 7}, xm[9] = {7, 7, 7, 7, 7, 7, 7, 7, 7};
        std::string j = I(k, b) + "." + I(same);
        mj_local2Global(d, xp, xm, pos, quat, b, same);
        w.d("local2Global.pos#" + j, xp, 3);
        w.d("local2Global.mat#" + j, xm, 9);
        mjtNum xp1[3] = {7, 7, 7}, xm1[9] = {7, 7, 7, 7, 7, 7, 7, 7, 7};
        mj_local2Global(d, xp1, NULL, pos, quat, b, same);
        mj_local2Global(d, NULL, xm1, pos, quat, b, same);
        mj_local2Global(d, xp1 + 1, xm1 + 1, NULL, NULL, b, same);
        w.d("local2Global.alone#" + j, xp1, 3);
        w.d("local2Global.alone_mat#" + j, xm1, 9);
      }
    }
  }
}

// The sensor stages at the reference's forward results, contacts included (touch sensors,
// cfrc_ext of contacts): mj_sensorPos, mj_sensorVel, mj_sensorAcc, each recorded.
inline void check_sensors(const mjModel* m, mjData* d, const Inputs& in, Writer& w) {
  for (int k = 0; k < in.nstate; k++) {
    at_state(m, d, in, k, true);
    load_contacts(d, *in.post, I(k));
    mju_zero(d->sensordata, m->nsensordata);
    std::string i = I(k);
    mj_sensorPos(m, d);
    w.d("pos.sensordata#" + i, d->sensordata, m->nsensordata);
    mj_sensorVel(m, d);
    w.d("vel.sensordata#" + i, d->sensordata, m->nsensordata);
    mj_sensorAcc(m, d);
    w.d("acc.sensordata#" + i, d->sensordata, m->nsensordata);
    w.d("cfrc_ext#" + i, d->cfrc_ext, 6 * m->nbody);
  }
}

// Collision detection alone at each state: the position stages it needs, then mj_collision;
// the contacts (every field, in order) and the contact-buffer warning.
inline void check_collision(const mjModel* m, mjData* d, const Inputs& in, Writer& w) {
  for (int k = 0; k < in.nstate; k++) {
    at_state(m, d, in, k, false);
    mj_kinematics(m, d);
    mj_comPos(m, d);
    mj_collision(m, d);
    std::string i = I(k);
    w.i1("ncon#" + i, d->ncon);
    dump_contacts(d, w, i);
    w.i("warning.contactfull#" + i, &d->warning[mjWARN_CONTACTFULL].lastinfo, 2);
  }
}

// Check groups that call nothing but the functions under test on the model (no mjData).
inline bool needs_data(const std::string& group) {
  return group != "names" && group != "integratePos" && group != "differentiatePos";
}

// Check groups evaluated at the states, by name; each runs isolated (see harness.cc).
inline std::vector<std::pair<std::string, Check>> state_checks() {
  return {
      {"forward", check_forward},
      {"step", check_step},
      {"jacSite", check_jac("jacSite")},
      {"jacBody", check_jac("jacBody")},
      {"jacBodyCom", check_jac("jacBodyCom")},
      {"jacGeom", check_jac("jacGeom")},
      {"jac", check_jac("jac")},
      {"jacPointAxis", check_jac("jacPointAxis")},
      {"fullM", check_fullM},
      {"mulM", check_mulM},
      {"mulM2", check_mulM2},
      {"solveM", check_solveM},
      {"consistency", check_consistency},
      {"integratePos", check_integratePos},
      {"differentiatePos", check_differentiatePos},
      {"names", check_names},
      {"inverse", check_inverse},
      {"objects", check_objects},
      {"sensors", check_sensors},
      {"collision", check_collision},
  };
}

// Groups whose results do not depend on the dynamics (no noise-floor allowance).
inline bool static_group(const std::string& group) {
  return group == "model" || group == "names" || group == "consistency" ||
         group == "integratePos" || group == "differentiatePos";
}

// Tolerance on the relative error (compare.h) of each check group. Dynamic groups also allow
// 1000 times the reference's noise floor of each quantity (harness.cc: state checks against
// forward at perturbed states, traj against a perturbed trajectory).
inline double tolerance(const std::string& group) {
  if (group == "model") return 1e-9;
  if (group == "traj") return 1e-8;
  return 1e-10;
}
