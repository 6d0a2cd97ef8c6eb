#include "app/run/key_interval.h"

namespace tumble::app {

int key_interval(int fps) {
    return 2 * fps;
}

} // namespace tumble::app
