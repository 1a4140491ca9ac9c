"use client";
// Copying a text to the clipboard, with what was copied to say so and a
// plain-language error when the browser refuses (an insecure page, a denied permission).
import { useState } from "react";

export function useCopy() {
  const [copied, setCopied] = useState<string | null>(null);
  const [copyError, setCopyError] = useState<{ message: string } | null>(null);
  const copy = async (what: string, text: string) => {
    setCopyError(null);
    try {
      await navigator.clipboard.writeText(text);
      setCopied(what);
    } catch {
      setCopyError({ message: "The browser did not allow copying: select the text and copy it by hand." });
    }
  };
  return { copied, copyError, copy };
}
