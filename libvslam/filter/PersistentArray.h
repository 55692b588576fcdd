#pragma once
/** \file PersistentArray.h
 * A persistent (copy-on-write) array: a 16-ary trie of reference-counted
 * nodes. Copying an array shares every node (O(1)); writing one element
 * copies only the nodes on its root-to-leaf path that are shared
 * (O(log16 n)), and writes in place where the path is already unique.
 *
 * This is what makes particle resampling cheap in vslam: a resampled
 * particle's landmark bank is a pointer copy, and the next Kalman update
 * of one landmark copies about log16(landmarks) small nodes, never the bank.
 *
 * Reference counts are plain integers: arrays that share nodes must be used
 * from one thread (the filter is single-threaded by design).
 */
#include <libvslam/filter/FreeList.h>

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <unordered_set>
#include <utility>

namespace vslam
{
template <typename T>
class PersistentArray
{
	static constexpr unsigned kBits = 4;
	static constexpr unsigned kFanout = 1u << kBits;
	static constexpr unsigned kMask = kFanout - 1;

	struct Node
	{
		uint32_t refs = 1;
	};
	struct Inner : Node
	{
		Node* child[kFanout] = {};
		VSLAM_FREELIST_ALLOCATED(Inner)
	};
	struct Leaf : Node
	{
		explicit Leaf(const T& v) : value(v) {}
		T value;
		VSLAM_FREELIST_ALLOCATED(Leaf)
	};

   public:
	PersistentArray() = default;
	PersistentArray(const PersistentArray& o)
		: m_root(o.m_root), m_size(o.m_size), m_levels(o.m_levels)
	{
		if (m_root) m_root->refs++;
	}
	PersistentArray(PersistentArray&& o) noexcept { swap(o); }
	PersistentArray& operator=(PersistentArray o) noexcept
	{
		swap(o);
		return *this;
	}
	~PersistentArray() { release(m_root, m_levels); }

	void swap(PersistentArray& o) noexcept
	{
		std::swap(m_root, o.m_root);
		std::swap(m_size, o.m_size);
		std::swap(m_levels, o.m_levels);
	}

	size_t size() const { return m_size; }
	bool empty() const { return m_size == 0; }

	const T& operator[](size_t i) const
	{
		const Node* n = m_root;
		for (unsigned level = m_levels; level > 0; level--)
			n = static_cast<const Inner*>(n)->child[digit(i, level)];
		return static_cast<const Leaf*>(n)->value;
	}
	const T& at(size_t i) const
	{
		checkIndex(i);
		return (*this)[i];
	}

	/** Writable access to element i: copies the shared nodes on its path. */
	T& mutate(size_t i)
	{
		checkIndex(i);
		Node** slot = &m_root;
		for (unsigned level = m_levels; level > 0; level--)
		{
			makeUnique(slot, level);
			slot = &static_cast<Inner*>(*slot)->child[digit(i, level)];
		}
		makeUnique(slot, 0);
		return static_cast<Leaf*>(*slot)->value;
	}

	void set(size_t i, const T& v) { mutate(i) = v; }

	void push_back(const T& v)
	{
		if (m_size == capacity())
		{
			auto* root = new Inner();
			root->child[0] = m_root;  // null when empty
			m_root = root;
			m_levels++;
		}
		Node** slot = &m_root;
		for (unsigned level = m_levels; level > 0; level--)
		{
			if (*slot == nullptr)
				*slot = new Inner();
			else
				makeUnique(slot, level);
			slot = &static_cast<Inner*>(*slot)->child[digit(m_size, level)];
		}
		*slot = new Leaf(v);
		m_size++;
	}

	template <class F>
	void forEach(F&& f) const
	{
		for (size_t i = 0; i < m_size; i++) f(i, (*this)[i]);
	}

	/** True if both arrays share their root (diagnostics and tests). */
	bool sharesRootWith(const PersistentArray& o) const
	{
		return m_root != nullptr && m_root == o.m_root;
	}

	/** Number of nodes reachable from this array but not from `other`
	 * (diagnostics and tests: the cost of a divergence). */
	size_t nodesNotIn(const PersistentArray& other) const
	{
		std::unordered_set<const Node*> theirs;
		collect(other.m_root, other.m_levels, theirs);
		std::unordered_set<const Node*> mine;
		collect(m_root, m_levels, mine);
		size_t n = 0;
		for (const Node* p : mine) n += theirs.count(p) == 0;
		return n;
	}

	/** Height of the trie (0 when empty). */
	unsigned levels() const { return m_levels; }

   private:
	Node* m_root = nullptr;
	size_t m_size = 0;
	unsigned m_levels = 0;  //!< inner levels above the leaves

	size_t capacity() const
	{
		return m_levels == 0 ? 0 : size_t(1) << (kBits * m_levels);
	}
	static unsigned digit(size_t i, unsigned level)
	{
		return static_cast<unsigned>(i >> (kBits * (level - 1))) & kMask;
	}
	void checkIndex(size_t i) const
	{
		if (i >= m_size) throw std::out_of_range("PersistentArray index");
	}

	/** Replaces *slot by a private copy if it is shared. `level` 0 = leaf. */
	static void makeUnique(Node** slot, unsigned level)
	{
		Node* n = *slot;
		if (n->refs == 1) return;
		Node* copy;
		if (level == 0)
			copy = new Leaf(static_cast<Leaf*>(n)->value);
		else
		{
			auto* in = new Inner(*static_cast<Inner*>(n));
			in->refs = 1;
			for (Node* c : in->child)
				if (c) c->refs++;
			copy = in;
		}
		n->refs--;  // still > 0: someone else holds it
		*slot = copy;
	}

	static void release(Node* n, unsigned level)
	{
		if (!n || --n->refs > 0) return;
		if (level == 0)
		{
			delete static_cast<Leaf*>(n);
			return;
		}
		auto* in = static_cast<Inner*>(n);
		for (Node* c : in->child) release(c, level - 1);
		delete in;
	}

	static void collect(
		const Node* n, unsigned level, std::unordered_set<const Node*>& out)
	{
		if (!n || !out.insert(n).second) return;
		if (level == 0) return;
		for (const Node* c : static_cast<const Inner*>(n)->child)
			collect(c, level - 1, out);
	}
};

}  // namespace vslam
