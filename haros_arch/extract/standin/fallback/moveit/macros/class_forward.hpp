// haros_arch stand-in: moveit_core's class forward macros (moveit/macros/class_forward.h,
// .hpp from Jazzy on), for a workspace that builds on an installed MoveIt. A class
// declared with MOVEIT_CLASS_FORWARD(Name) gets the pointer aliases NamePtr,
// NameConstPtr, NameWeakPtr, NameConstWeakPtr, NameUniquePtr and NameConstUniquePtr.
// Not known, the macro read as a type made ``MOVEIT_CLASS_FORWARD(Stage);`` a variable
// named Stage that hid the class (moveit_task_constructor: "must use 'struct' tag").
#ifndef HAROS_STANDIN_MOVEIT_MACROS_CLASS_FORWARD_HPP
#define HAROS_STANDIN_MOVEIT_MACROS_CLASS_FORWARD_HPP
#include <memory>

#define MOVEIT_DECLARE_PTR(Name, Type)                       \
  using Name##Ptr = std::shared_ptr<Type>;                   \
  using Name##ConstPtr = std::shared_ptr<const Type>;        \
  using Name##WeakPtr = std::weak_ptr<Type>;                 \
  using Name##ConstWeakPtr = std::weak_ptr<const Type>;      \
  using Name##UniquePtr = std::unique_ptr<Type>;             \
  using Name##ConstUniquePtr = std::unique_ptr<const Type>

#define MOVEIT_DECLARE_PTR_MEMBER(Type) MOVEIT_DECLARE_PTR(, Type)

#define MOVEIT_CLASS_FORWARD(C) \
  class C;                      \
  MOVEIT_DECLARE_PTR(C, C)

#define MOVEIT_STRUCT_FORWARD(C) \
  struct C;                      \
  MOVEIT_DECLARE_PTR(C, C)

#endif  // HAROS_STANDIN_MOVEIT_MACROS_CLASS_FORWARD_HPP
