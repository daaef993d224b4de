// Placeholder so the library links before the model issue lands; replaced by the model work.
#include "opspace/model.hpp"
