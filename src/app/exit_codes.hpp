#pragma once
// Documented exit codes of the `ryushi` command (README, docs/cli.md).
namespace ryushi {
enum ExitCode : int {
  kExitDone = 0,
  kExitInternal = 1,
  kExitBadInput = 2,
  kExitNumericalFailure = 3,
  kExitInterrupted = 130,
};
}  // namespace ryushi
