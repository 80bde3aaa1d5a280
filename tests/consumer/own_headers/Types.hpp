// The consumer's own header of a name that signorini's core package uses too: the installed
// signorini headers include theirs with the package path, so this one must never be reached.
#error "the consumer's own Types.hpp was included in place of signorini's core/Types.hpp"
