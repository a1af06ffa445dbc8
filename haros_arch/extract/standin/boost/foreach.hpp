// haros_arch stand-in: BOOST_FOREACH as the range-based for it stands for (the
// iteration order is no matter to the extraction)
#ifndef HAROS_STANDIN_BOOST_FOREACH_HPP
#define HAROS_STANDIN_BOOST_FOREACH_HPP
#define BOOST_FOREACH(VAR, COL) for (VAR : COL)
#define BOOST_REVERSE_FOREACH(VAR, COL) for (VAR : COL)
#endif
