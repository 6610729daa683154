// `quaternia reference parameters|cli`: docs/parameters.md and docs/cli.md, printed as Markdown
// from the declarations themselves (the parameter table, the presets, the CLI11 commands), so
// that the committed pages cannot fall behind the code: ctest's Docs.ParameterReferenceIsCurrent
// and Docs.CliReferenceIsCurrent compare them. Not listed by `quaternia --help`: it is for the
// project, not for drawing.
#pragma once

#include <string>

#include <CLI/CLI.hpp>

namespace quaternia {

struct ReferenceCommandOptions {
    CLI::App* parameters = nullptr;  // the `reference parameters` subcommand
    CLI::App* cli = nullptr;         // the `reference cli` subcommand
};

void addReferenceCommand(CLI::App& app, ReferenceCommandOptions& options);

// Prints the page asked for to standard output; `app` is quaternia's whole command line, which
// the cli page describes.
int runReferenceCommand(const CLI::App& app, const ReferenceCommandOptions& options);

// docs/parameters.md: every scene key by section, then the presets.
std::string parameterReferencePage();

// docs/cli.md: every command of `quaternia` (`app`) and of quaternia-mpi with each option's
// names, type, default and help.
std::string cliReferencePage(const CLI::App& app);

}  // namespace quaternia
