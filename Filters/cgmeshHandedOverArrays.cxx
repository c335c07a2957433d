#include "cgmeshHandedOverArrays.h"

#include <mutex>
#include <unordered_map>

namespace cgmesh
{

namespace
{

// VTK's free function receives only the buffer's address, so the owners are found by it. Arrays
// are created and freed on any thread (a pipeline may release an output anywhere): one lock.
struct HandedOverRegistry
{
  std::mutex mutex;
  std::unordered_map<const void*, std::unique_ptr<HandedOverStorage>> storageAt;
};

HandedOverRegistry& registry()
{
  static HandedOverRegistry* instance = new HandedOverRegistry; // outlives static destructors
  return *instance;
}

} // namespace

void keepHandedOverStorage(const void* data, std::unique_ptr<HandedOverStorage> storage)
{
  HandedOverRegistry& handedOver = registry();
  const std::lock_guard<std::mutex> lock(handedOver.mutex);
  handedOver.storageAt[data] = std::move(storage);
}

void releaseHandedOverStorage(void* data)
{
  std::unique_ptr<HandedOverStorage> storage;
  {
    HandedOverRegistry& handedOver = registry();
    const std::lock_guard<std::mutex> lock(handedOver.mutex);
    const auto found = handedOver.storageAt.find(data);
    if (found == handedOver.storageAt.end())
    {
      return;
    }
    storage = std::move(found->second);
    handedOver.storageAt.erase(found);
  }
  // freed here, outside the lock
}

std::size_t handedOverStorageCount()
{
  HandedOverRegistry& handedOver = registry();
  const std::lock_guard<std::mutex> lock(handedOver.mutex);
  return handedOver.storageAt.size();
}

} // namespace cgmesh
