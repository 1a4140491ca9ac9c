// Long lists drawn as far as they are seen: a trial of 100k events would
// otherwise put 100k rows in the page. Rows have one fixed height, so the
// rows in view follow from the scroll position alone; a margin of rows is
// drawn either side, so a short list is drawn whole and scrolling shows no
// gap. The list keeps its full height (space above and below), so the
// scrollbar tells where one is.
import { useCallback, useEffect, useState } from "react";

/** Which rows to draw: [from, to) of `count` rows of `rowHeight` px, seen through `viewport` px scrolled `scrollTop` px. */
export function rowsInView({
  count,
  rowHeight,
  scrollTop,
  viewport,
  margin,
}: {
  count: number;
  rowHeight: number;
  scrollTop: number;
  viewport: number;
  margin: number;
}) {
  const first = Math.floor(Math.max(0, scrollTop) / rowHeight);
  const last = Math.ceil((Math.max(0, scrollTop) + viewport) / rowHeight);
  const from = Math.max(0, Math.min(count, first - margin));
  const to = Math.min(count, Math.max(from, last + margin));
  return { from, to, before: from * rowHeight, after: (count - to) * rowHeight };
}

/** The rows of a scrolled list to draw, and a way to bring one into view (for the keyboard and the playhead). */
export function useRowsInView(count: number, rowHeight: number, viewport: number, margin = 50) {
  const [box, setBox] = useState<HTMLElement | null>(null);
  const [scrollTop, setScrollTop] = useState(0);
  useEffect(() => {
    if (!box) return;
    const onScroll = () => setScrollTop(box.scrollTop);
    box.addEventListener("scroll", onScroll, { passive: true });
    return () => box.removeEventListener("scroll", onScroll);
  }, [box]);
  const reveal = useCallback(
    (index: number) => {
      if (!box) return;
      const top = index * rowHeight;
      if (top < box.scrollTop) box.scrollTop = top;
      else if (top + rowHeight > box.scrollTop + box.clientHeight) box.scrollTop = top + rowHeight - box.clientHeight;
      setScrollTop(box.scrollTop);
    },
    [box, rowHeight],
  );
  return { ref: setBox, reveal, ...rowsInView({ count, rowHeight, scrollTop, viewport, margin }) };
}
