#pragma once
/** \file FreeList.h
 * A free list for fixed-size nodes (landmark-bank trie nodes, path nodes):
 * a filter update allocates and frees about a thousand such nodes, which
 * through malloc cost a fifth of the update time. Nodes are recycled per
 * thread; memory goes back to the system when the thread ends. Only an
 * allocation cache: it holds no state the filter's results depend on.
 */
#include <cstddef>
#include <new>

namespace vslam
{
template <size_t Size>
class FreeList
{
	static_assert(Size >= sizeof(void*), "node too small for the free list");

   public:
	static void* allocate()
	{
		List& l = list();
		if (!l.head) return ::operator new(Size);
		void* p = l.head;
		l.head = *static_cast<void**>(p);
		return p;
	}
	static void deallocate(void* p) noexcept
	{
		List& l = list();
		*static_cast<void**>(p) = l.head;
		l.head = p;
	}

   private:
	struct List
	{
		void* head = nullptr;
		~List()
		{
			while (head)
			{
				void* next = *static_cast<void**>(head);
				::operator delete(head);
				head = next;
			}
		}
	};
	static List& list()
	{
		thread_local List l;
		return l;
	}
};

/** Gives a node type class-specific operator new/delete from FreeList. */
#define VSLAM_FREELIST_ALLOCATED(T)                                              \
	static void* operator new(size_t n)                                          \
	{                                                                            \
		return n == sizeof(T) ? ::vslam::FreeList<sizeof(T)>::allocate()         \
							  : ::operator new(n);                               \
	}                                                                            \
	static void operator delete(void* p, size_t n) noexcept                      \
	{                                                                            \
		if (n == sizeof(T))                                                      \
			::vslam::FreeList<sizeof(T)>::deallocate(p);                         \
		else                                                                     \
			::operator delete(p);                                                \
	}
}  // namespace vslam
