// A syntax-stage header that reaches up into decide/: the layout check must reject it.
#pragma once
#include "derivations/decide/prove.hpp"
