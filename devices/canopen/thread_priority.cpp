#include "devices/canopen/thread_priority.h"

#include <pthread.h>
#include <sched.h>

namespace cutcell::canopen {

bool raiseCallingThreadToFifo(int priority) {
    sched_param p{};
    p.sched_priority = priority;
    return pthread_setschedparam(pthread_self(), SCHED_FIFO, &p) == 0;
}

} // namespace cutcell::canopen
