// The CLI11 types the commands' headers name. Only the files that build or read the command line
// include CLI11 itself: every file that includes it compiles its validator objects again, which
// costs seconds per file (most of the program's build under the sanitizers).
#pragma once

namespace CLI {
class App;
class ParseError;
}  // namespace CLI
