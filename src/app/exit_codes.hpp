#pragma once
// Documented exit codes of the `ryushi` command (README, docs/cli.md).
namespace ryushi {
enum ExitCode : int {
  kExitDone = 0,
  kExitInternal = 1,
  kExitBadInput = 2,
  kExitNumericalFailure = 3,
  kExitOutputFailed = 4,  // an output file could not be written (disk full, size limit, no permission)
  kExitInterrupted = 130,
};
}  // namespace ryushi
