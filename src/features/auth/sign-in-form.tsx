"use client";
import { useState, type FormEvent } from "react";
import { authClient } from "@/lib/auth-client";
import { Button } from "@/ui/button";
import { Field, Input } from "@/ui/field";
import { Problem } from "@/ui/problem";

const MESSAGES: Record<number, string> = {
  401: "That email and password do not match an account.",
  403: "This account cannot sign in. Ask an administrator.",
  429: "Too many sign-in attempts. Wait a minute, then try again.",
};

export function SignInForm() {
  const [email, setEmail] = useState("");
  const [password, setPassword] = useState("");
  const [error, setError] = useState<string | null>(null);
  const [busy, setBusy] = useState(false);

  async function submit(event: FormEvent) {
    event.preventDefault();
    setBusy(true);
    setError(null);
    const { error } = await authClient.signIn.email({ email, password });
    setBusy(false);
    if (error) return setError(MESSAGES[error.status] ?? error.message ?? "Sign-in failed. Please try again.");
    // Loaded whole, not routed to: a page loaded before signing in keeps the stranger's security policy,
    // which lets it reach nothing but this site (src/proxy.ts), not the trial runtime.
    window.location.replace("/studies");
  }

  return (
    <form onSubmit={submit} method="post" className="space-y-4">
      <Field label="Email" required>
        {(p) => (
          <Input {...p} type="email" autoComplete="username" value={email} onChange={(e) => setEmail(e.target.value)} />
        )}
      </Field>
      <Field label="Password" required>
        {(p) => (
          <Input
            {...p}
            type="password"
            autoComplete="current-password"
            value={password}
            onChange={(e) => setPassword(e.target.value)}
          />
        )}
      </Field>
      {error && <Problem error={{ message: error }} />}
      <Button type="submit" className="w-full" disabled={busy}>
        {busy ? "Signing in…" : "Sign in"}
      </Button>
    </form>
  );
}
