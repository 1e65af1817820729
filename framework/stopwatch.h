// The two clocks a render's time can be measured on: wall-clock time, or the CPU time of the
// whole process (every thread's added up). On a machine that other jobs share, wall-clock time
// also counts the time slices the system gave to them, and two renderers timed one after the
// other get different shares; CPU time counts only the work of the process (`render --clock cpu`,
// `converge --clock cpu`, the bench scripts). With T threads busy, T CPU seconds pass per
// wall-clock second, so CPU-time figures compare only with CPU-time figures of the same threads.
#pragma once
#include <chrono>
#include <ctime>
#include <string>

namespace ps {

enum class TimeClock { Wall, Cpu };

// Seconds since an arbitrary start, on the given clock: only differences mean something.
inline double clockSeconds(TimeClock clock) {
    if (clock == TimeClock::Cpu) {
#if defined(CLOCK_PROCESS_CPUTIME_ID)
        timespec ts;
        if (clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts) == 0) return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
#endif
        return double(std::clock()) / CLOCKS_PER_SEC;  // (ISO C: the process's processor time)
    }
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

// "wall" or "cpu": the command-line spelling (--clock); false for anything else.
inline bool parseClock(const std::string& name, TimeClock& clock) {
    if (name != "wall" && name != "cpu") return false;
    clock = name == "cpu" ? TimeClock::Cpu : TimeClock::Wall;
    return true;
}

// How a figure names its clock: "wall-clock seconds" or "CPU seconds (process, all threads)".
inline const char* clockUnit(TimeClock clock) {
    return clock == TimeClock::Cpu ? "CPU seconds (process, all threads)" : "wall-clock seconds";
}

}  // namespace ps
