// Must NOT compile: app/run/ cannot see app/regression/, which stands on it. Built only by the
// test House.RunCannotIncludeRegression, which passes when the compiler says the header is not
// found.
#include "app/regression/suite.h"
