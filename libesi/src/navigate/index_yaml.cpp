#include "navigate/index.hpp"
namespace esi::navigate {
void index_yaml(Index&) {}
}
