// raylab / raylab-reference: the same command line, linked with assignments/ or solutions/.
#include "raylab/cli.h"

int main(int argc, char** argv) { return raylab::run_cli(argc, argv); }
