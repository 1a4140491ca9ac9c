"use client";
// A page's keyboard shortcuts, from one listener on the window. The handler
// that runs is the latest render's, put in place as that render is committed
// (a layout effect), before the browser can deliver another key: a key pressed
// the moment the page shows a new state acts on that state. With a passive
// effect a key could come first and meet the previous render's handler: the
// wizard's second N, pressed as the first step appeared, once sent "start"
// again and was refused.
import { useEffect, useLayoutEffect, useRef } from "react";

export function useKeys(onKey: (e: KeyboardEvent) => void) {
  const latest = useRef(onKey);
  useLayoutEffect(() => {
    latest.current = onKey;
  });
  useEffect(() => {
    const listen = (e: KeyboardEvent) => latest.current(e);
    window.addEventListener("keydown", listen);
    return () => window.removeEventListener("keydown", listen);
  }, []);
}

/** Keys typed into a field are text, not shortcuts. */
export const isTyping = (target: EventTarget | null) =>
  target instanceof HTMLElement &&
  (target.isContentEditable || ["INPUT", "TEXTAREA", "SELECT"].includes(target.tagName));
