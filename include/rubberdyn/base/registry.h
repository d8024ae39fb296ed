#ifndef rubberdyn_base_registry_h
#define rubberdyn_base_registry_h

#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace rubberdyn
{
  /**
   * A registry of named plugins of one kind, in ASPECT's manner: each
   * plugin (a constitutive law, a study; later a contact kind or a
   * postprocessor) registers itself from its own translation unit through
   * a static initialiser, with a description for the parameter
   * documentation and its functions (@p Entry: how to declare its
   * parameters, how to create it). The parameter entry that selects a
   * plugin takes its pattern and documentation from here, so a new plugin
   * needs no edit anywhere else.
   *
   * There is one registry per @p Entry type, instance(), a function-local
   * static: safe against the initialisation order of the registering
   * translation units.
   */
  template <typename Entry>
  class Registry
  {
  public:
    /** The registry of this kind of plugin. */
    static Registry &
    instance()
    {
      static Registry registry;
      return registry;
    }

    /**
     * Add @p entry under @p name; returns 0, to initialise a static
     * variable.
     *
     * @throws std::logic_error if the name is taken: two plugins of one
     * name would silently replace each other.
     */
    int
    add(const std::string &name,
        const std::string &description,
        const Entry &      entry)
    {
      if (!items.emplace(name, Item{description, entry}).second)
        throw std::logic_error("two plugins are registered as '" + name +
                               "'");
      return 0;
    }

    /** The entry named @p name, or nullptr. */
    const Entry *
    find(const std::string &name) const
    {
      const auto it = items.find(name);
      return it == items.end() ? nullptr : &it->second.entry;
    }

    /** The registered names, sorted. */
    std::vector<std::string>
    names() const
    {
      std::vector<std::string> result;
      for (const auto &item : items)
        result.push_back(item.first);
      return result;
    }

    /** The names joined by '|', for dealii::Patterns::Selection. */
    std::string
    pattern() const
    {
      std::string result;
      for (const auto &item : items)
        result += (result.empty() ? "" : "|") + item.first;
      return result;
    }

    /**
     * @p heading followed by one line "'name': description" per plugin,
     * for the documentation of the entry that selects one.
     */
    std::string
    documentation(const std::string &heading) const
    {
      std::string result = heading;
      for (const auto &item : items)
        result += "\n'" + item.first + "': " + item.second.description;
      return result;
    }

    /** Call @p function(name, entry) for every plugin, in name order. */
    template <typename Function>
    void
    for_each(const Function &function) const
    {
      for (const auto &item : items)
        function(item.first, item.second.entry);
    }

  private:
    Registry() = default;

    struct Item
    {
      std::string description;
      Entry       entry;
    };
    std::map<std::string, Item> items;
  };
} // namespace rubberdyn

#endif
