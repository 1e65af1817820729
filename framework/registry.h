// One registry of named entries per type T, filled before main by static initialisers: the
// integrators (integrator.h), the program's commands (app/command.h), the camera models
// (camera.h), the algorithm options (integrator.h), and whatever a lesson lets later lessons
// register (a path filter, an extra technique). A lesson registers its entries at namespace scope
// in a .cpp file that is linked as an object file, so the registration is kept:
//   static const bool registered = ps::Registry<IntegratorInfo>::add("pt", {...});
// Entries keep the order they were added in (for one type, a program's static initialisers run
// in one fixed order); list() also gives them sorted by name.
#pragma once
#include <algorithm>
#include <string>
#include <utility>
#include <vector>

namespace ps {

template <class T>
class Registry {
public:
    struct Entry {
        std::string name;
        T value;
    };
    // Adds value under name (a name added twice: the later entry wins find()); returns true.
    static bool add(const std::string& name, T value) {
        entries().push_back({name, std::move(value)});
        return true;
    }
    // The entry of this name, nullptr if there is none.
    static const T* find(const std::string& name) {
        const std::vector<Entry>& all = entries();
        for (auto it = all.rbegin(); it != all.rend(); ++it)
            if (it->name == name) return &it->value;
        return nullptr;
    }
    // Every entry in the order added.
    static const std::vector<Entry>& inOrder() { return entries(); }
    // Every entry, sorted by name (a name added twice: once, the later entry).
    static std::vector<Entry> sorted() {
        std::vector<Entry> list;
        for (const Entry& e : entries())
            if (find(e.name) == &e.value) list.push_back(e);
        std::sort(list.begin(), list.end(), [](const Entry& a, const Entry& b) { return a.name < b.name; });
        return list;
    }
    // The names, sorted, joined by ", " ("none" when there are none): for messages.
    static std::string names() {
        std::string s;
        for (const Entry& e : sorted()) s += (s.empty() ? "" : ", ") + e.name;
        return s.empty() ? std::string("none") : s;
    }

private:
    static std::vector<Entry>& entries() {
        static std::vector<Entry> all;
        return all;
    }
};

}  // namespace ps
