"use client";
// A choice from a short list, built on Radix Select: keyboard and screen
// reader behaviour come with it. Takes the props Field hands its control.
import * as RadixSelect from "@radix-ui/react-select";
import { Check, ChevronDown } from "lucide-react";

interface SelectProps<T extends string> {
  id?: string;
  value: T;
  onValueChange: (value: T) => void;
  options: Array<{ value: T; label: string; hint?: string }>;
  required?: boolean;
  "aria-invalid"?: boolean;
  "aria-describedby"?: string;
}

export function Select<T extends string>({ id, value, onValueChange, options, required, ...aria }: SelectProps<T>) {
  return (
    <RadixSelect.Root value={value} required={required} onValueChange={(v) => onValueChange(v as T)}>
      <RadixSelect.Trigger
        id={id}
        {...aria}
        className="flex h-10 w-full items-center justify-between rounded-md border border-slate-300 bg-white px-3 py-2 text-sm shadow-sm focus:border-brand-500 focus:outline-none focus:ring-2 focus:ring-brand-500/30"
      >
        <RadixSelect.Value />
        <RadixSelect.Icon>
          <ChevronDown className="h-4 w-4 text-slate-500" />
        </RadixSelect.Icon>
      </RadixSelect.Trigger>
      <RadixSelect.Portal>
        <RadixSelect.Content
          position="popper"
          sideOffset={4}
          className="z-50 min-w-[var(--radix-select-trigger-width)] rounded-md border border-slate-200 bg-white p-1 shadow-lg"
        >
          <RadixSelect.Viewport>
            {options.map((o) => (
              <RadixSelect.Item
                key={o.value}
                value={o.value}
                className="relative flex cursor-default select-none flex-col rounded py-1.5 pl-7 pr-3 text-sm outline-none data-[highlighted]:bg-brand-50"
              >
                <RadixSelect.ItemIndicator className="absolute left-2 top-2">
                  <Check className="h-3.5 w-3.5" />
                </RadixSelect.ItemIndicator>
                <RadixSelect.ItemText>{o.label}</RadixSelect.ItemText>
                {o.hint && <span className="text-xs text-slate-500">{o.hint}</span>}
              </RadixSelect.Item>
            ))}
          </RadixSelect.Viewport>
        </RadixSelect.Content>
      </RadixSelect.Portal>
    </RadixSelect.Root>
  );
}
