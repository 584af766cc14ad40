// Loader checks, built against each library (tests/loader.rs):
//   loader verdict FILE...   one line per file: "load <sizes>", "reject <message>",
//                            "crash <signal>" or "hang" (each load in a child, 20 s limit)
//   loader time N FILE...    loads every file N times; prints the seconds taken
#define _DEFAULT_SOURCE
#include <mujoco/mujoco.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

static double now(void) {
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return t.tv_sec + 1e-9 * t.tv_nsec;
}

// The first line of the message, with the file's directory left out (paths differ by run).
static void one_line(char* s) {
  for (char* p = s; *p; p++) {
    if (*p == '\n' || *p == '\r') {
      *p = 0;
      break;
    }
  }
}

static void verdict(const char* file) {
  int fd[2];
  if (pipe(fd)) return;
  fflush(stdout);
  pid_t pid = fork();
  if (pid == 0) {
    close(fd[0]);
    dup2(fd[1], 1);
    char err[1000] = "";
    mjModel* m = mj_loadXML(file, NULL, err, sizeof err);
    if (m) {
      printf("load nq=%d nv=%d nu=%d na=%d nbody=%d njnt=%d ngeom=%d nsite=%d nmesh=%d ntendon=%d "
             "nsensor=%d neq=%d nkey=%d\n",
             m->nq, m->nv, m->nu, m->na, m->nbody, m->njnt, m->ngeom, m->nsite, m->nmesh,
             m->ntendon, m->nsensor, m->neq, m->nkey);
      mj_deleteModel(m);
    } else {
      one_line(err);
      printf("reject %s\n", err);
    }
    fflush(stdout);
    _exit(0);
  }
  close(fd[1]);
  char buf[2000];
  size_t n = 0;
  ssize_t r;
  int ws = 0, done = 0;
  for (int t = 0; t < 2000 && !done; t++) {
    if (waitpid(pid, &ws, WNOHANG) == pid) done = 1;
    else usleep(10000);
  }
  if (!done) {
    kill(pid, SIGKILL);
    waitpid(pid, &ws, 0);
    printf("hang\n");
    close(fd[0]);
    return;
  }
  while (n + 1 < sizeof buf && (r = read(fd[0], buf + n, sizeof buf - 1 - n)) > 0) n += r;
  buf[n] = 0;
  close(fd[0]);
  if (WIFSIGNALED(ws)) printf("crash %d\n", WTERMSIG(ws));
  else if (n == 0) printf("crash exit %d\n", WEXITSTATUS(ws));
  else fputs(buf, stdout);
}

static void quiet(const char* msg) { (void)msg; }

int main(int argc, char** argv) {
  if (argc >= 3 && !strcmp(argv[1], "verdict")) {
    mju_user_warning = quiet;
    for (int i = 2; i < argc; i++) verdict(argv[i]);
    return 0;
  }
  if (argc >= 4 && !strcmp(argv[1], "time")) {
    int reps = atoi(argv[2]);
    double t0 = now();
    for (int k = 0; k < reps; k++) {
      for (int i = 3; i < argc; i++) {
        char err[1000] = "";
        mjModel* m = mj_loadXML(argv[i], NULL, err, sizeof err);
        if (!m) {
          fprintf(stderr, "%s: %s\n", argv[i], err);
          return 1;
        }
        mj_deleteModel(m);
      }
    }
    printf("%.6f\n", now() - t0);
    return 0;
  }
  fprintf(stderr, "usage: loader verdict FILE... | loader time N FILE...\n");
  return 2;
}
