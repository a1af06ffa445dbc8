"""The cursors the C++ walk runs on (``cursors.Node``) answer as libclang's own do.

A ``Node`` keeps what libclang told it and takes its children from one visit of the
whole subtree; each fact is checked here against plain cursors of the same unit, walked
one visit per node as the binding does, on code with the shapes that make libclang's
cursors differ by path (declarations in a group, statements under lambdas, default
arguments, a range-for, member initialisers, templates).
"""

from __future__ import annotations

from clang.cindex import Cursor, CursorKind

from haros_arch.extract.cpp import cursors, toolchain

SOURCE = """
namespace ns {
int twice(int x, int y = 2) { return x * y; }
struct Box {
  Box(int v) : value(v), other(v + 1) {}
  int get() const { int a = value, b = a + 1; return a > 0 ? b : twice(a); }
  int value;
  int other = 3;
};
template <typename T> T pick(T a, T b) { return a < b ? b : a; }
int walk(const int (&items)[3]) {
  int total = 0;
  for (int item : items) {
    auto add = [&total](int v) { total += v; return total; };
    if (item > 1 && add(item)) { total = twice(total); }
    else { switch (item) { case 1: break; default: total--; } }
  }
  Box box(total);
  while (total > 10) { total = pick(total, box.get()) - 1; }
  return twice(total);
}
}
"""
NAME = "/tmp/haros_arch_cursors_test.cpp"


def _unit():
    return toolchain.index().parse(NAME, args=["-x", "c++", "-std=c++17", "-nostdinc"],
                                   unsaved_files=[(NAME, SOURCE)])


def _plain_children(cursor: Cursor) -> list[Cursor]:
    return list(Cursor.get_children(cursor))


def _pairs(node: cursors.Node, plain: Cursor):
    """Every (node, plain cursor) of the two walks of the main file's code, in step."""
    stack = [(node, plain)]
    while stack:
        one, other = stack.pop()
        yield one, other
        mine, theirs = list(one.get_children()), _plain_children(other)
        assert len(mine) == len(theirs), (one.kind, one.spelling)
        stack.extend(zip(mine, theirs, strict=True))


def _main_file_code(tu):
    root = cursors.root(tu)
    for node, plain in zip(root.get_children(), _plain_children(tu.cursor), strict=True):
        if node.location.file is not None and node.location.file.name == NAME:
            yield node, plain


def test_nodes_answer_as_plain_cursors():
    tu = _unit()
    count = 0
    for top, plain_top in _main_file_code(tu):
        for node, plain in _pairs(top, plain_top):
            count += 1
            assert type(node) is cursors.Node
            assert bytes(node) == bytes(plain)  # the bytes a visit of the parent gives
            assert node == plain and plain == node and hash(node) == hash(plain)
            assert node.kind == plain.kind and node.spelling == plain.spelling
            start, end = node.extent.start, node.extent.end
            assert (start.offset, end.offset) == (plain.extent.start.offset,
                                                  plain.extent.end.offset)
            assert (node.location.line, node.location.column) == (plain.location.line,
                                                                  plain.location.column)
            assert (node.location.file is None) == (plain.location.file is None)
            if plain.location.file is not None:
                assert node.location.file.name == plain.location.file.name
            for name in ("referenced", "semantic_parent", "canonical"):
                mine, theirs = getattr(node, name), getattr(plain, name)
                assert (mine is None) == (theirs is None), (name, node.kind)
                if mine is not None:
                    assert type(mine) is cursors.Node and mine == theirs
            if node.kind == CursorKind.CALL_EXPR:
                assert list(node.get_arguments()) == list(Cursor.get_arguments(plain))
            assert node.is_definition() == plain.is_definition()
            assert [t.spelling for t in node.get_tokens()] == [
                t.spelling for t in plain.get_tokens()]
    assert count > 150


def test_one_node_per_cursor_and_clang_equality():
    tu = _unit()
    nodes = [n for top, _ in _main_file_code(tu) for n in top.walk_preorder()]
    assert nodes == [n for top, _ in _main_file_code(tu) for n in top.walk_preorder()]
    walk = next(n for n in nodes if n.kind == CursorKind.FUNCTION_DECL
                and n.spelling == "walk")
    # asked twice, a fact is the same object: the walks share one tree
    assert walk.get_definition() is walk.get_definition()
    calls = [n for n in walk.walk_preorder() if n.kind == CursorKind.CALL_EXPR
             and n.spelling == "twice"]
    assert len(calls) == 2 and calls[0].referenced is calls[1].referenced
    assert calls[0] != calls[1]
    # a declaration met in its group and through a reference: equal, as clang says,
    # though libclang's bytes differ (whether it came first in its group)
    get = next(n for n in nodes if n.kind == CursorKind.CXX_METHOD and n.spelling == "get")
    b_decl = next(n for n in get.walk_preorder() if n.kind == CursorKind.VAR_DECL
                  and n.spelling == "b")
    b_refs = [n.referenced for n in get.walk_preorder()
              if n.kind == CursorKind.DECL_REF_EXPR and n.spelling == "b"]
    assert b_refs and all(ref == b_decl for ref in b_refs)
    assert all(Cursor.__eq__(ref, b_decl) for ref in b_refs)
    assert {hash(ref) for ref in b_refs} == {hash(b_decl)}
    # compared with None, either way round, a node is not equal (libclang takes no None)
    assert b_decl.__eq__(None) is False and b_decl.__ne__(None) is True
    assert [ref for ref in [None] if ref == b_decl] == []  # None asks the node
    # any two nodes: equal exactly when libclang says so
    sample = [*get.walk_preorder(), *(n.referenced for n in get.walk_preorder()
                                      if n.referenced is not None)]
    for one in sample:
        for other in sample:
            assert (one == other) == bool(Cursor.__eq__(one, other))


def test_children_of_a_subtree_visit_equal_a_visit_of_each_node():
    tu = _unit()
    for top, _ in _main_file_code(tu):
        for node in top.walk_preorder():
            alone = node._visit_children()  # one visit of this node alone
            assert [bytes(c) for c in node.get_children()] == [bytes(c) for c in alone]


def test_a_nodes_writes_are_asked_once_and_are_a_plain_cursors():
    """``writes.writes_of`` keeps a node's writes on the node (the walks of a unit ask
    each node again); what it keeps is what a plain cursor of the same place gives."""
    from haros_arch.extract.cpp.writes import writes_of

    source = {NAME: SOURCE.encode()}
    tu = _unit()
    seen = 0
    for top, plain_top in _main_file_code(tu):
        for node, plain in _pairs(top, plain_top):
            found = writes_of(node, source)
            assert writes_of(node, source) is found  # kept, not read again
            theirs = writes_of(plain, source)
            assert [(w.whole, w.target.kind, w.at.kind) for w in found] == [
                (w.whole, w.target.kind, w.at.kind) for w in theirs]
            seen += len(found)
    assert seen >= 6  # total = 0, += v, total = twice(...), total--, box, total = pick


def _plain_preorder(plain: Cursor) -> list[bytes]:
    """The binding's preorder walk of a plain cursor, one visit per node."""
    found, stack = [], [plain]
    while stack:
        cursor = stack.pop()
        found.append(bytes(cursor))
        stack.extend(reversed(_plain_children(cursor)))
    return found


def test_a_kept_preorder_is_the_walk_whichever_node_is_walked_first():
    """``Node.walk_preorder`` keeps each node's preorder and takes a descendant's kept
    one whole: walked from the leaves up (each node's list made from its children's),
    from the top down, or twice, every node's walk is the binding's walk of the plain
    cursor."""
    for order in ("leaves first", "top first"):
        tu = _unit()
        pairs = [pair for top, plain_top in _main_file_code(tu)
                 for pair in _pairs(top, plain_top)]
        if order == "leaves first":
            pairs.reverse()  # (every node after its descendants)
        for node, plain in pairs:
            expected = _plain_preorder(plain)
            assert [bytes(n) for n in node.walk_preorder()] == expected, (order, node.kind)
            assert [bytes(n) for n in node.walk_preorder()] == expected  # kept
        walk = next(n for n, _ in pairs if n.kind == CursorKind.FUNCTION_DECL
                    and n.spelling == "walk")
        assert len(list(walk.walk_preorder())) > 60


def _plain_last_first(plain: Cursor) -> list[bytes]:
    """A walk that pops a stack and pushes each cursor's children in order."""
    found, stack = [], [plain]
    while stack:
        cursor = stack.pop()
        found.append(bytes(cursor))
        stack.extend(_plain_children(cursor))
    return found


def test_a_kept_last_first_walk_is_the_stack_walk_whichever_node_is_walked_first():
    """``values._walk`` of a node is its kept ``walk_last_first``, made from a
    descendant's kept list where there is one: from the leaves up, from the top down,
    or twice, every node's walk is the stack walk of the plain cursor."""
    from haros_arch.extract.cpp.values import _walk

    for order in ("leaves first", "top first"):
        tu = _unit()
        pairs = [pair for top, plain_top in _main_file_code(tu)
                 for pair in _pairs(top, plain_top)]
        if order == "leaves first":
            pairs.reverse()
        for node, plain in pairs:
            expected = _plain_last_first(plain)
            assert [bytes(n) for n in _walk(node)] == expected, (order, node.kind)
            assert [bytes(n) for n in _walk(node)] == expected
            assert [bytes(n) for n in _walk(plain)] == expected  # a plain cursor's walk
        walk = next(n for n, _ in pairs if n.kind == CursorKind.FUNCTION_DECL
                    and n.spelling == "walk")
        assert len(list(_walk(walk))) > 60


def test_a_subtrees_writes_are_kept_and_are_a_plain_walks():
    """``writes.writes_in`` keeps on a node the writes of its whole subtree in preorder:
    for every node, what a plain cursor's walk gives with ``writes_of`` of each cursor,
    whether the subtree's nodes were asked before or after."""
    from haros_arch.extract.cpp.writes import writes_in, writes_of

    source = {NAME: SOURCE.encode()}

    def shape(writes):
        return [(w.whole, bytes(w.target), bytes(w.at),
                 None if w.value is None else bytes(w.value)) for w in writes]

    for order in ("leaves first", "top first"):
        tu = _unit()
        pairs = [pair for top, plain_top in _main_file_code(tu)
                 for pair in _pairs(top, plain_top)]
        if order == "leaves first":
            pairs.reverse()
        seen = 0
        for node, plain in pairs:
            found = writes_in(node, source)
            assert writes_in(node, source) is found  # kept, not read again
            expected = [w for each in Cursor.walk_preorder(plain)
                        for w in writes_of(each, source)]
            assert shape(found) == shape(expected), (order, node.kind)
            assert shape(writes_in(plain, source)) == shape(expected)
            seen = max(seen, len(found))
        assert seen >= 5  # walk's total = 0, += v, total = twice(...), total--, box, ...
