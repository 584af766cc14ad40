// User callbacks (tests/callbacks.rs): every mjcb_* but mjcb_time installed with deterministic
// effects, 500 steps of models/extra/callbacks.xml; prints the state, sensors, contacts and how
// often each callback ran, identical on both libraries.
#include <math.h>
#include <mujoco/mujoco.h>
#include <stdio.h>
#include <string.h>

static int calls[6];

// exported by 2.2.2 outside mujoco.h
int mj_jacDifPair(const mjModel* m, const mjData* d, int* chain, int b1, int b2,
                  const mjtNum* pos1, const mjtNum* pos2, mjtNum* jac1p, mjtNum* jac2p,
                  mjtNum* jacdifp, mjtNum* jac1r, mjtNum* jac2r, mjtNum* jacdifr);

static void control(const mjModel* m, mjData* d) {
  calls[0]++;
  d->ctrl[0] = 0.5 * cos(2 * d->time);
  d->ctrl[1] = sin(3 * d->time);
}

static void passive(const mjModel* m, mjData* d) {
  calls[1]++;
  for (int i = 0; i < m->nv; i++) d->qfrc_passive[i] -= 0.05 * d->qvel[i];
}

static mjtNum gain(const mjModel* m, const mjData* d, int id) {
  calls[2]++;
  return 2.0 + 0.1 * d->actuator_length[id];
}

static mjtNum bias(const mjModel* m, const mjData* d, int id) {
  calls[3]++;
  return -0.5 * d->actuator_velocity[id] + 0.01 * d->actuator_force[id];
}

static mjtNum dyn(const mjModel* m, const mjData* d, int id) {
  calls[4]++;
  int j = id - (m->nu - m->na);
  return (d->ctrl[id] - d->act[j]) / 0.1;
}

static void sensor(const mjModel* m, mjData* d, int stage) {
  calls[5]++;
  for (int i = 0; i < m->nsensor; i++) {
    if (m->sensor_type[i] != mjSENS_USER || m->sensor_needstage[i] != stage) continue;
    mjtNum* out = d->sensordata + m->sensor_adr[i];
    if (stage == mjSTAGE_VEL) {
      out[0] = d->qvel[0] * 2;
      out[1] = d->cvel[6 + 2];
    } else {
      out[0] = d->qacc[1] + d->qfrc_constraint[0];
    }
  }
}

// a clock that ticks once per call: timer durations count the calls
static mjtNum clock_ticks = 0;
static mjtNum tick_clock(void) { return clock_ticks += 1; }

// discard contacts of geoms with odd id sums (keeping some the built-in filter discards:
// parent and child, the same weld body); counts its calls
static int filter_calls = 0;
static int filter(const mjModel* m, mjData* d, int g1, int g2) {
  filter_calls++;
  return (g1 + g2) % 2;
}

int main(int argc, char** argv) {
  char err[1000] = "";
  mjModel* m = mj_loadXML(argv[1], NULL, err, sizeof err);
  if (!m) {
    printf("load error: %s\n", err);
    return 1;
  }
  mjData* d = mj_makeData(m);
  mjcb_control = control;
  mjcb_passive = passive;
  mjcb_act_gain = gain;
  mjcb_act_bias = bias;
  mjcb_act_dyn = dyn;
  mjcb_sensor = sensor;
  mjcb_contactfilter = filter;
  mjcb_time = tick_clock;
  for (int s = 1; s <= 500; s++) {
    mj_step(m, d);
    if (s % 50 == 0) {
      printf("step %d time %.17g ncon %d\n", s, d->time, d->ncon);
      for (int i = 0; i < m->nq; i++) printf(" %.17g", d->qpos[i]);
      printf("\n");
      for (int i = 0; i < m->nv; i++) printf(" %.17g", d->qvel[i]);
      printf("\n");
      for (int i = 0; i < m->na; i++) printf(" %.17g", d->act[i]);
      for (int i = 0; i < m->nsensordata; i++) printf(" %.17g", d->sensordata[i]);
      for (int i = 0; i < m->nu; i++) printf(" %.17g", d->actuator_force[i]);
      printf("\n");
    }
  }
  for (int i = 0; i < mjNTIMER; i++)
    printf("timer %d: %.17g over %d\n", i, d->timer[i].duration, d->timer[i].number);
  mj_inverse(m, d);
  mj_step1(m, d);
  mj_step2(m, d);
  printf("after inverse, step1, step2: clock %.17g\n", clock_ticks);
  // the collision function table, called directly for every geom pair in table order
  mjContact con[mjMAXCONPAIR];
  for (int g1 = 0; g1 < m->ngeom; g1++) {
    for (int g2 = 0; g2 < m->ngeom; g2++) {
      mjfCollision f = mjCOLLISIONFUNC[m->geom_type[g1]][m->geom_type[g2]];
      if (!f || g1 == g2) continue;
      int n = f(m, d, con, g1, g2, 0.5);
      for (int k = 0; k < n; k++)
        printf("collide %d %d: %.17g %.17g %.17g %.17g %.17g %.17g %.17g\n", g1, g2, con[k].dist,
               con[k].pos[0], con[k].pos[1], con[k].pos[2], con[k].frame[0], con[k].frame[1],
               con[k].frame[2]);
    }
  }
  // mj_jacDifPair for every body pair, dense then sparse
  for (int sparse = 0; sparse < 2; sparse++) {
    m->opt.jacobian = sparse ? mjJAC_SPARSE : mjJAC_DENSE;
    mjtNum p1[3] = {0.1, 0.2, 0.3}, p2[3] = {-0.2, 0.1, 0.4};
    mjtNum j1p[3 * 64], j2p[3 * 64], jdp[3 * 64], j1r[3 * 64], j2r[3 * 64], jdr[3 * 64];
    int chain[64];
    for (int b1 = 0; b1 < m->nbody; b1++) {
      for (int b2 = 0; b2 < m->nbody; b2++) {
        // entries the function does not write (same body, sparse) stay as the caller left them
        memset(jdp, 0, sizeof jdp);
        memset(jdr, 0, sizeof jdr);
        int n = mj_jacDifPair(m, d, chain, b1, b2, p1, p2, j1p, j2p, jdp, j1r, j2r, jdr);
        printf("jacDifPair %d %d %d: n %d", sparse, b1, b2, n);
        for (int k = 0; k < 3 * n; k++) printf(" %.17g %.17g", jdp[k], jdr[k]);
        printf("\n");
      }
    }
  }
  m->opt.jacobian = mjJAC_AUTO;
  printf("calls: control %d passive %d gain %d bias %d dyn %d sensor %d filter %d\n", calls[0],
         calls[1], calls[2], calls[3], calls[4], calls[5], filter_calls);
  mj_resetCallbacks();
  mj_deleteData(d);
  mj_deleteModel(m);
  return 0;
}
