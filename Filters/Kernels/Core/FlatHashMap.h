// A hash map with open addressing (linear probing) in one array. The refinement makes and looks up
// millions of short-lived edge → midpoint entries in thousands of small per-partition maps; the
// node-based std::unordered_map spent a fifth of a 65,536-partition run in malloc and free.
// Insert and find only: entries are never erased one by one.
#ifndef cgmesh_FlatHashMap_h
#define cgmesh_FlatHashMap_h

#include <cstddef>
#include <utility>
#include <vector>

namespace cgmesh
{

// `EmptyKey::value()` is a key that is never stored: it marks a free slot.
template <typename Key, typename Value, typename Hash, typename EmptyKey>
class FlatHashMap
{
public:
  std::size_t size() const { return this->Count; }
  bool empty() const { return this->Count == 0; }

  void clear()
  {
    this->Slots.clear();
    this->Count = 0;
  }

  // Room for `count` entries without growing.
  void reserve(std::size_t count)
  {
    std::size_t capacity = 16;
    while (capacity < 2 * count)
    {
      capacity *= 2;
    }
    if (capacity > this->Slots.size())
    {
      this->rehash(capacity);
    }
  }

  const Value* find(const Key& key) const
  {
    if (this->Slots.empty())
    {
      return nullptr;
    }
    const std::size_t mask = this->Slots.size() - 1;
    for (std::size_t i = Hash()(key) & mask;; i = (i + 1) & mask)
    {
      const Slot& slot = this->Slots[i];
      if (slot.first == key)
      {
        return &slot.second;
      }
      if (slot.first == EmptyKey::value())
      {
        return nullptr;
      }
    }
  }

  bool contains(const Key& key) const { return this->find(key) != nullptr; }

  // The slot a look-up of the key reads first (null when the map has no slots), for the caller
  // to prefetch: a large map's look-ups are cache misses one after another otherwise.
  const void* firstSlotOf(const Key& key) const
  {
    return this->Slots.empty() ? nullptr : &this->Slots[Hash()(key) & (this->Slots.size() - 1)];
  }

  // Calls visit(key, value) for every entry, in slot order.
  template <typename Visit>
  void forEach(Visit&& visit) const
  {
    for (const Slot& slot : this->Slots)
    {
      if (!(slot.first == EmptyKey::value()))
      {
        visit(slot.first, slot.second);
      }
    }
  }

  // Inserts (key, value) unless the key is there; returns whether it inserted.
  bool emplace(const Key& key, const Value& value)
  {
    bool inserted = false;
    this->findOrEmplace(key, value, inserted);
    return inserted;
  }

  // The key's value, after inserting (key, value) if the key was not there (`inserted` says
  // which): one probe where find() after a failed emplace() takes two.
  Value& findOrEmplace(const Key& key, const Value& value, bool& inserted)
  {
    if (2 * (this->Count + 1) > this->Slots.size())
    {
      this->rehash(this->Slots.empty() ? 16 : 2 * this->Slots.size());
    }
    const std::size_t mask = this->Slots.size() - 1;
    for (std::size_t i = Hash()(key) & mask;; i = (i + 1) & mask)
    {
      Slot& slot = this->Slots[i];
      if (slot.first == key)
      {
        inserted = false;
        return slot.second;
      }
      if (slot.first == EmptyKey::value())
      {
        slot = Slot(key, value);
        ++this->Count;
        inserted = true;
        return slot.second;
      }
    }
  }

private:
  using Slot = std::pair<Key, Value>;

  void rehash(std::size_t capacity)
  {
    std::vector<Slot> old = std::move(this->Slots);
    this->Slots.assign(capacity, Slot(EmptyKey::value(), Value()));
    this->Count = 0;
    for (const Slot& slot : old)
    {
      if (!(slot.first == EmptyKey::value()))
      {
        this->emplace(slot.first, slot.second);
      }
    }
  }

  std::vector<Slot> Slots; // size 0 or a power of two, at most half full
  std::size_t Count = 0;
};

} // namespace cgmesh

#endif
