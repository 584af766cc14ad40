// Waits for a child process with a time limit (capi-tests/child.h and the harness).
#pragma once
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

// Waits at most `seconds` for child `pid`, in short naps first (most children end within
// milliseconds), then 10 ms ones. Returns 1 with its status in *ws when it ended; else kills
// and reaps it and returns 0.
static inline int wait_child(pid_t pid, int seconds, int* ws) {
  for (long waited = 0, nap = 500; waited < 1000000L * seconds; waited += nap) {
    nap = waited < 200000 ? 500 : 10000;
    if (waitpid(pid, ws, WNOHANG) == pid) return 1;
    usleep(nap);
  }
  kill(pid, SIGKILL);
  waitpid(pid, ws, 0);
  return 0;
}
