#include <CLI/CLI.hpp>

#include <iostream>

int main(int argc, char** argv) {
  CLI::App app{"eigenwalker-cli: load walking motion capture, build eigenwalker models, "
               "reconstruct 3D walkers from 2D views"};
  app.require_subcommand(1);
  CLI11_PARSE(app, argc, argv);
  return 0;
}
