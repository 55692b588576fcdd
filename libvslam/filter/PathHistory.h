#pragma once
/** \file PathHistory.h
 * A particle's path hypothesis s^t as a persistent singly linked list of
 * (timestamp, pose): particles resampled from one ancestor share its
 * history, so copying a particle is O(1) and memory holds only the
 * lineages that survive. Destruction is iterative (no deep recursion on
 * hour-long paths).
 */
#include <libvslam/filter/FreeList.h>
#include <libvslam/models/SE2.h>
#include <mrpt/core/Clock.h>

#include <cstdint>
#include <utility>
#include <vector>

namespace vslam
{
class PathHistory
{
	struct Node
	{
		uint32_t refs = 1;
		se2::Pose pose;
		mrpt::Clock::time_point t;
		Node* parent = nullptr;
		VSLAM_FREELIST_ALLOCATED(Node)
	};

   public:
	struct Entry
	{
		mrpt::Clock::time_point t;
		se2::Pose pose;
	};

	PathHistory() = default;
	PathHistory(const PathHistory& o) : m_head(o.m_head), m_length(o.m_length)
	{
		if (m_head) m_head->refs++;
	}
	PathHistory(PathHistory&& o) noexcept { swap(o); }
	PathHistory& operator=(PathHistory o) noexcept
	{
		swap(o);
		return *this;
	}
	~PathHistory() { release(m_head); }

	void swap(PathHistory& o) noexcept
	{
		std::swap(m_head, o.m_head);
		std::swap(m_length, o.m_length);
	}

	void push(mrpt::Clock::time_point t, const se2::Pose& pose)
	{
		auto* n = new Node();
		n->pose = pose;
		n->t = t;
		n->parent = m_head;  // takes over our reference to the old head
		m_head = n;
		m_length++;
	}

	size_t length() const { return m_length; }
	bool empty() const { return m_head == nullptr; }

	/** The path, oldest first. */
	std::vector<Entry> toVector() const
	{
		std::vector<Entry> out(m_length);
		size_t i = m_length;
		for (const Node* n = m_head; n; n = n->parent)
			out[--i] = Entry{n->t, n->pose};
		return out;
	}

   private:
	Node* m_head = nullptr;
	size_t m_length = 0;

	static void release(Node* n)
	{
		while (n && --n->refs == 0)
		{
			Node* parent = n->parent;
			delete n;
			n = parent;
		}
	}
};
}  // namespace vslam
