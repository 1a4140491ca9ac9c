"use client";
import { Slot } from "@radix-ui/react-slot";
import { cva, type VariantProps } from "class-variance-authority";
import { useEffect, useState, type ButtonHTMLAttributes } from "react";
import { cn } from "./cn";

// On a touch screen every button is at least 44 px high (WCAG 2.5.5); a mouse keeps them compact.
const button = cva(
  "inline-flex items-center justify-center gap-2 rounded-md font-medium transition-colors focus-visible:outline-none focus-visible:ring-2 focus-visible:ring-brand-500 focus-visible:ring-offset-2 disabled:pointer-events-none disabled:opacity-50 pointer-coarse:min-h-11",
  {
    variants: {
      variant: {
        primary: "bg-brand-600 text-white hover:bg-brand-700",
        secondary: "border border-slate-300 bg-white text-slate-800 hover:bg-slate-100",
        ghost: "text-slate-700 hover:bg-slate-100",
        danger: "bg-red-600 text-white hover:bg-red-700",
      },
      size: { sm: "h-8 px-3 text-sm", md: "h-10 px-4 text-sm", lg: "h-12 px-6 text-base" },
    },
    defaultVariants: { variant: "primary", size: "md" },
  },
);

export interface ButtonProps extends ButtonHTMLAttributes<HTMLButtonElement>, VariantProps<typeof button> {
  asChild?: boolean;
}

export function Button({ className, variant, size, asChild, type = "button", disabled, ...props }: ButtonProps) {
  const Component = asChild ? Slot : "button";
  // A form sent before the page is interactive would go as a plain browser
  // submit (a password in the address bar): submit buttons wait for React.
  const [interactive, setInteractive] = useState(false);
  useEffect(() => setInteractive(true), []);
  const waiting = type === "submit" && !interactive;
  return (
    <Component
      type={asChild ? undefined : type}
      disabled={disabled || waiting}
      className={cn(button({ variant, size }), className)}
      {...props}
    />
  );
}
