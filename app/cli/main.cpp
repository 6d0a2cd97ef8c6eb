// tumble: rigid bodies stepped by a small exact physics core, drawn headlessly with OSMesa.
// The command line lives in the cli library (app/cli/tumble_main.cpp).
#include "app/cli/tumble_main.h"

int main(int argc, char** argv) {
    return tumble::app::tumble_main(argc, argv);
}
