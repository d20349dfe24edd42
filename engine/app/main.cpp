// meshedit: entry point. All the work is in cli.cpp so tests can call it in-process.
#include "app/cli.h"

int main(int argc, char** argv) { return meshedit::run_cli(argc, argv); }
