#include <rubberdyn/materials/volumetric_function.h>

#include <stdexcept>

namespace rubberdyn
{
  namespace materials
  {
    std::string
    volumetric_function_names()
    {
      return "polynomial|log squared|Simo-Taylor";
    }



    VolumetricFunction
    volumetric_function_from_name(const std::string &name)
    {
      if (name == "polynomial")
        return VolumetricFunction::polynomial;
      if (name == "log squared")
        return VolumetricFunction::log_squared;
      if (name == "Simo-Taylor")
        return VolumetricFunction::simo_taylor;
      // The parameter pattern lists the valid names; reaching this is a
      // programming error, not bad input.
      throw std::logic_error("unknown volumetric function '" + name + "'");
    }



    std::string
    volumetric_function_name(const VolumetricFunction function)
    {
      switch (function)
        {
          case VolumetricFunction::polynomial:
            return "polynomial";
          case VolumetricFunction::log_squared:
            return "log squared";
          case VolumetricFunction::simo_taylor:
            return "Simo-Taylor";
        }
      throw std::logic_error("unknown volumetric function");
    }
  } // namespace materials
} // namespace rubberdyn
