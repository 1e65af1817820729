// How the worker threads wait. The render loop runs one OpenMP parallel loop per iteration, so
// the threads meet at a barrier after every iteration. By default libgomp makes a thread that
// waits there spin (busy-wait) for a while; on a machine that is busy with anything else (a
// build, a second render, the tests running two at a time) the spinning threads take the CPU
// from the ones with work, and small renders ran 7x slower (28.6 s instead of 4.4 s for a
// 32 x 32 Cornell box at 2000 spp on 2 cores under load). Passive waiting (sleep at once) costs
// a few microseconds per iteration instead.
#pragma once

namespace ps {

// Call first thing in main(argc, argv). libgomp reads OMP_WAIT_POLICY once, when the program
// is loaded, so setting it now is too late for this process: if the environment does not set
// it, the program runs itself again with OMP_WAIT_POLICY=PASSIVE (the same arguments; on
// failure it simply goes on). Set OMP_WAIT_POLICY yourself to choose otherwise. Linux only (it
// runs /proc/self/exe); elsewhere it does nothing.
void preferPassiveWaiting(char** argv);

}  // namespace ps
