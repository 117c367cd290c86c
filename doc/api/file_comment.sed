# The first comment block of a header is its file's description: doxygen (doc/api/Doxyfile)
# reads it so when its first line ends with \file (lines are neither added nor removed).
1s|^//!.*|& \\file|
