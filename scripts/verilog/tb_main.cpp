// main() of the chip testbench's Verilator model (what `verilator --binary` generates for a
// --timing model); scripts/run-chip.sh links it with a hierarchical build, which cannot
// take --binary (Verilator 5.006 passes --exe and --main on to the hierarchical blocks).
#include "verilated.h"
#include "Vtb.h"
#include <memory>

int main(int argc, char** argv) {
    const std::unique_ptr<VerilatedContext> contextp{new VerilatedContext};
    contextp->commandArgs(argc, argv);
    const std::unique_ptr<Vtb> topp{new Vtb{contextp.get(), ""}};
    while (!contextp->gotFinish()) {
        topp->eval();
        if (!topp->eventsPending()) break;
        contextp->time(topp->nextTimeSlot());
    }
    topp->final();
    return 0;
}
