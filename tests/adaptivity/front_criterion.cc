// The rupture-front criterion's decisions for a cell at a distance from
// the one active node, plain and graded (rings one level coarser per
// band's width): the levels a cell reaches after repeated passes at each
// distance, and that a front that advances one band between two
// adaptations finds the graded cells at most one level short (one pass),
// the plain ones up to <Levels> short.

#include <rupture/adaptivity/front_criterion.h>

#include <iostream>
#include <vector>

namespace
{
  using rupture::Adaptivity::Decision;
  using rupture::Adaptivity::FrontCriterion;

  const double       band   = 100;
  const unsigned int base   = 0;
  const unsigned int finest = 3;

  /// The cell's size (m) at @p level: 80 m at the base, halved per level.
  double
  size_at(const unsigned int level)
  {
    return 80. / (1 << level);
  }

  /// The level a cell at @p distance from the node reaches from @p level by
  /// refining while the criterion says so, and the passes that took.
  std::pair<unsigned int, unsigned int>
  settle(const FrontCriterion<2> &front,
         const double             distance,
         unsigned int             level)
  {
    unsigned int passes = 0;
    while (front.decide(dealii::Point<2>(distance, 0),
                        size_at(level),
                        level,
                        base,
                        finest) == Decision::refine)
      {
        ++level;
        ++passes;
      }
    return {level, passes};
  }
} // namespace



int
main()
{
  const std::vector<dealii::Point<2>> node = {dealii::Point<2>(0, 0)};
  for (const bool graded : {false, true})
    {
      const FrontCriterion<2> front(node, band, graded);
      std::cout << (graded ? "graded" : "plain") << ": level from the base "
                << "at a distance of";
      for (const double d : {0., 90., 140., 190., 240., 290., 340., 400.})
        std::cout << " " << d << " m: " << settle(front, d, base).first << ";";
      std::cout << "\n";
      // The front one band nearer: the most passes any cell needs.
      unsigned int most = 0;
      for (double d = 0; d < 600; d += 5)
        {
          const unsigned int now = settle(front, d, base).first;
          most = std::max(most, settle(front, d - band, now).second);
        }
      std::cout << "  passes after the front moved one band: at most " << most
                << "\n";
      // Coarsening: the finest cell stays while a node is within twice the
      // band, a cell one level coarser within four bands (graded).
      for (const unsigned int level : {3u, 2u})
        {
          std::cout << "  a level-" << level << " cell is kept up to";
          double d = 0;
          while (front.decide(dealii::Point<2>(d, 0),
                              size_at(level),
                              level,
                              base,
                              finest) != Decision::coarsen)
            d += 5;
          std::cout << " " << d << " m\n";
        }
      // A cell away from the fault (its finest level is its base): only
      // coarsened, beyond twice the band, graded or not.
      std::cout << "  a cell above its base away from the fault coarsens "
                << "at 300 m: "
                << (front.decide(dealii::Point<2>(300, 0), 10, 1, 0, 0) ==
                        Decision::coarsen ?
                      "yes" :
                      "no")
                << ", at 200 m: "
                << (front.decide(dealii::Point<2>(200, 0), 10, 1, 0, 0) ==
                        Decision::coarsen ?
                      "yes" :
                      "no")
                << "\n";
    }
}
