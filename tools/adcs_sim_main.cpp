// adcs-sim: run the paper scenarios (see `adcs-sim help` and src/cli/commands.hpp).
#include "cli/commands.hpp"

int main(int argc, char** argv) { return adcs::sim::cli::cli_main(argc, argv); }
