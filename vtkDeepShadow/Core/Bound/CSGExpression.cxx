#include "Core/Bound/CSGExpression.h"

#include <algorithm>
#include <cctype>

namespace deepshadow
{

bool CSGNode::Evaluate(uint32_t leafStates) const
{
  switch (this->Operation)
  {
    case CSGOperation::Leaf:
      return ((leafStates >> this->Leaf) & 1u) != 0;
    case CSGOperation::Union:
      return std::any_of(this->Operands.begin(), this->Operands.end(),
        [leafStates](const CSGNode& n) { return n.Evaluate(leafStates); });
    case CSGOperation::Intersection:
      return std::all_of(this->Operands.begin(), this->Operands.end(),
        [leafStates](const CSGNode& n) { return n.Evaluate(leafStates); });
    case CSGOperation::Difference:
    {
      if (!this->Operands.front().Evaluate(leafStates))
      {
        return false;
      }
      return std::none_of(this->Operands.begin() + 1, this->Operands.end(),
        [leafStates](const CSGNode& n) { return n.Evaluate(leafStates); });
    }
  }
  return false;
}

double CSGNode::TriangleWork(const std::vector<double>& leafTriangles, double* resultTriangles) const
{
  if (this->Operation == CSGOperation::Leaf)
  {
    const size_t leaf = static_cast<size_t>(this->Leaf);
    if (resultTriangles)
    {
      *resultTriangles = leaf < leafTriangles.size() ? leafTriangles[leaf] : 0.0;
    }
    return 0.0;
  }
  double work = 0.0, accumulated = 0.0;
  for (size_t i = 0; i < this->Operands.size(); ++i)
  {
    double operand = 0.0;
    work += this->Operands[i].TriangleWork(leafTriangles, &operand);
    if (i > 0)
    {
      work += accumulated + operand;
    }
    accumulated += operand;
  }
  if (resultTriangles)
  {
    *resultTriangles = accumulated;
  }
  return work;
}

int CSGNode::MaxLeaf() const
{
  int result = this->Operation == CSGOperation::Leaf ? this->Leaf : -1;
  for (const CSGNode& operand : this->Operands)
  {
    result = std::max(result, operand.MaxLeaf());
  }
  return result;
}

std::string CSGNode::ToString() const
{
  if (this->Operation == CSGOperation::Leaf)
  {
    return CSGExpression::LeafName(this->Leaf);
  }
  std::string text = this->Operation == CSGOperation::Union ? "union("
    : this->Operation == CSGOperation::Intersection         ? "intersection("
                                                            : "difference(";
  for (size_t i = 0; i < this->Operands.size(); ++i)
  {
    text += (i ? "," : "") + this->Operands[i].ToString();
  }
  return text + ")";
}

std::string CSGExpression::LeafName(int leaf)
{
  return std::string(1, static_cast<char>('A' + leaf));
}

namespace
{
class Parser
{
public:
  Parser(const std::string& text, int leafCount)
    : Text(text)
    , LeafCount(leafCount)
  {
  }

  bool Parse(CSGNode& node, std::string& error)
  {
    if (!this->Expression(node) || (this->Skip(), this->Position != this->Text.size()))
    {
      if (this->Error.empty())
      {
        this->Fail("unexpected '" + this->Text.substr(this->Position, 1) + "'");
      }
      error = this->Error;
      return false;
    }
    return true;
  }

private:
  void Skip()
  {
    while (this->Position < this->Text.size() && std::isspace(static_cast<unsigned char>(this->Text[this->Position])))
    {
      ++this->Position;
    }
  }
  bool Fail(const std::string& message)
  {
    if (this->Error.empty())
    {
      const std::string shown = this->Text.size() <= 60 ? this->Text : this->Text.substr(0, 57) + "...";
      this->Error = "CSG expression \"" + shown + "\", at character " +
        std::to_string(this->Position + 1) + ": " + message;
    }
    return false;
  }
  bool Expect(char c)
  {
    this->Skip();
    if (this->Position >= this->Text.size() || this->Text[this->Position] != c)
    {
      return this->Fail(std::string("expected '") + c + "'" +
        (this->Position >= this->Text.size() ? " before the end" : ""));
    }
    ++this->Position;
    return true;
  }
  bool Expression(CSGNode& node, int depth = 0)
  {
    this->Skip();
    if (depth > CSGExpression::MaxDepth)
    {
      return this->Fail("operations nested deeper than " + std::to_string(CSGExpression::MaxDepth));
    }
    const size_t start = this->Position;
    while (this->Position < this->Text.size() && std::isalpha(static_cast<unsigned char>(this->Text[this->Position])))
    {
      ++this->Position;
    }
    std::string word = this->Text.substr(start, this->Position - start);
    if (word.empty())
    {
      return this->Fail(this->Position >= this->Text.size() ? "expected a bound or an operation before the end"
                                                            : "expected a bound (A, B, ...) or an operation");
    }
    std::transform(word.begin(), word.end(), word.begin(),
      [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (word.size() == 1)
    {
      node.Operation = CSGOperation::Leaf;
      node.Leaf = word[0] - 'a';
      if (node.Leaf >= this->LeafCount)
      {
        this->Position = start;
        return this->Fail("bound " + CSGExpression::LeafName(node.Leaf) + " is not given (" +
          std::to_string(this->LeafCount) + (this->LeafCount == 1 ? " bound" : " bounds") + ")");
      }
      return true;
    }
    if (word == "union")
    {
      node.Operation = CSGOperation::Union;
    }
    else if (word == "intersection" || word == "inter")
    {
      node.Operation = CSGOperation::Intersection;
    }
    else if (word == "difference" || word == "diff")
    {
      node.Operation = CSGOperation::Difference;
    }
    else
    {
      this->Position = start;
      return this->Fail("unknown operation '" + word + "' (union, intersection/inter, difference/diff)");
    }
    if (!this->Expect('('))
    {
      return false;
    }
    do
    {
      node.Operands.emplace_back();
      if (!this->Expression(node.Operands.back(), depth + 1))
      {
        return false;
      }
      this->Skip();
    } while (this->Position < this->Text.size() && this->Text[this->Position] == ',' && ++this->Position);
    if (node.Operands.size() < 2)
    {
      return this->Fail(word + " needs at least two operands");
    }
    return this->Expect(')');
  }

  const std::string& Text;
  int LeafCount;
  size_t Position = 0;
  std::string Error;
};
}

bool CSGExpression::Parse(const std::string& text, int leafCount, CSGExpression& result, std::string& error)
{
  if (leafCount < 1 || leafCount > 26)
  {
    error = "a CSG expression needs between 1 and 26 bounds, not " + std::to_string(leafCount);
    return false;
  }
  if (text.find_first_not_of(" \t\n") == std::string::npos)
  {
    result = UnionOf(leafCount);
    return true;
  }
  CSGExpression parsed;
  parsed.LeafCount = leafCount;
  if (!Parser(text, leafCount).Parse(parsed.RootNode, error))
  {
    return false;
  }
  result = parsed;
  return true;
}

CSGExpression CSGExpression::UnionOf(int leafCount)
{
  CSGExpression result;
  result.LeafCount = leafCount;
  if (leafCount == 1)
  {
    return result; // the root is leaf A
  }
  result.RootNode.Operation = CSGOperation::Union;
  for (int i = 0; i < leafCount; ++i)
  {
    CSGNode leaf;
    leaf.Leaf = i;
    result.RootNode.Operands.push_back(leaf);
  }
  return result;
}

std::vector<uint32_t> CSGExpression::TruthTable() const
{
  const uint32_t states = 1u << std::min(this->LeafCount, MaxLeaves);
  std::vector<uint32_t> table((states + 31) / 32, 0u);
  for (uint32_t s = 0; s < states; ++s)
  {
    if (this->Evaluate(s))
    {
      table[s / 32] |= 1u << (s % 32);
    }
  }
  return table;
}

}
