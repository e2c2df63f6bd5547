// The CLI11 types the commands' headers name. Only the files that build or read the command line
// include CLI11 itself: every file that includes it compiles CLI11's validator objects again,
// the slowest part of compiling the program.
#pragma once

namespace CLI {
class App;
class ParseError;
}  // namespace CLI
