import type { Metadata } from "next";
import type { ReactNode } from "react";
import { ApiProvider } from "@/lib/trpc";
import "./globals.css";

export const metadata: Metadata = {
  title: "HRIStudio",
  description: "Wizard-of-Oz studies for human-robot interaction",
};

export default function RootLayout({ children }: { children: ReactNode }) {
  return (
    <html lang="en">
      <body>
        <ApiProvider>{children}</ApiProvider>
      </body>
    </html>
  );
}
