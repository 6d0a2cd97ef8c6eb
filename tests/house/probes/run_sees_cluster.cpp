// Must NOT compile: app/run/ cannot see app/cluster/, the room above it (checkpoints and shards
// drive runs, never the other way round). Built only by the test House.RunCannotIncludeCluster,
// which passes when the compiler says the header is not found.
#include "app/cluster/checkpoint.h"
