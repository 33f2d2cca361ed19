// nprquake: see engine.h.
#include "app/engine.h"

int main(int argc, char** argv) {
    return nq::run_nprquake(argc, argv);
}
