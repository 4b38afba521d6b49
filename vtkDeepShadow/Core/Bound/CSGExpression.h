// A Boolean expression over named closed solids (the leaves of a CSG tree), e.g.
// "union(A,diff(B,C))". Shared by the CGAL filter (which evaluates it on meshes) and by the
// per-ray bound (which evaluates it on the leaves' inside/outside states, paper 000 sec. 3).
//
// Grammar: expr := NAME | OP '(' expr (',' expr)+ ')'; OP is union, intersection / inter,
// difference / diff (case-insensitive); n-ary operations fold left: diff(A,B,C) = (A-B)-C.
// NAME is a leaf: a letter A..Z (the bounds in the order given), case-insensitive.
#ifndef deepshadow_CSGExpression_h
#define deepshadow_CSGExpression_h

#include "vtkDeepShadowCoreModule.h"

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace deepshadow
{

enum class CSGOperation
{
  Leaf,
  Union,
  Intersection,
  Difference
};

struct VTKDEEPSHADOWCORE_EXPORT CSGNode
{
  CSGOperation Operation = CSGOperation::Leaf;
  int Leaf = 0; // for Leaf: 0 = A, 1 = B, ...
  std::vector<CSGNode> Operands;

  /** Whether a point is inside, given each leaf's state (bit i: inside leaf i). */
  bool Evaluate(uint32_t leafStates) const;
  /** Highest leaf index used, -1 if none. */
  int MaxLeaf() const;
  /**
   * The triangles the Boolean operations of this node take, all told, given each leaf's
   * triangle count: an n-ary operation folds left, each binary step taking both operands'
   * triangles and its result counted as their sum (an upper bound a corefinement rarely
   * exceeds). A leaf takes nothing: it is only converted and checked.
   */
  double TriangleWork(const std::vector<double>& leafTriangles, double* resultTriangles = nullptr) const;
  /** The expression written back, e.g. "union(A,difference(B,C))". */
  std::string ToString() const;
};

class VTKDEEPSHADOWCORE_EXPORT CSGExpression
{
public:
  /** Leaves a per-ray expression may have (its truth table has 2^MaxLeaves entries). */
  static constexpr int MaxLeaves = 8;
  /**
   * Operations nested deeper are refused: parsing and evaluating recurse, and a string of
   * 100000 "union(A," would overflow the stack (26 leaves never need more than a few levels).
   */
  static constexpr int MaxDepth = 64;

  /**
   * Parses `text` for `leafCount` leaves. Empty text means the union of all leaves. Returns
   * false with `error` naming the problem and its position on bad syntax, an unknown
   * operation, a leaf name beyond the leaves given, or nesting deeper than MaxDepth. The
   * error quotes at most 60 characters of `text`.
   */
  static bool Parse(const std::string& text, int leafCount, CSGExpression& result, std::string& error);
  /** The union of `leafCount` leaves (one leaf: the leaf itself). */
  static CSGExpression UnionOf(int leafCount);

  const CSGNode& Root() const { return this->RootNode; }
  int GetLeafCount() const { return this->LeafCount; }
  bool Evaluate(uint32_t leafStates) const { return this->RootNode.Evaluate(leafStates); }
  /**
   * The expression as a truth table over every combination of leaf states: bit s of word
   * s / 32 is Evaluate(s). Needs LeafCount <= MaxLeaves; the GPU looks states up in it.
   */
  std::vector<uint32_t> TruthTable() const;
  std::string ToString() const { return this->RootNode.ToString(); }

  /** Name of leaf i: "A", "B", ... */
  static std::string LeafName(int leaf);

private:
  CSGNode RootNode;
  int LeafCount = 0;
};

}
#endif
