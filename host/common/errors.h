// The error type and exit codes are part of the library's interface (brdfbake/error.h).
#pragma once
#include "brdfbake/error.h"
