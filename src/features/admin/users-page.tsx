"use client";
import { useMutation, useQuery, useQueryClient } from "@tanstack/react-query";
import { useState, type FormEvent } from "react";
import { SYSTEM_ROLES, type SystemRole } from "@/core/access/policy";
import { useTRPC } from "@/lib/trpc";
import { Button } from "@/ui/button";
import { Field, Input, NativeSelect } from "@/ui/field";
import { fieldError, Problem } from "@/ui/problem";
import { Badge, Card } from "@/ui/surface";
import { ListView } from "@/ui/list-view";
import { Td, Th } from "@/ui/table";

export function UsersPage({ selfId }: { selfId: string }) {
  const trpc = useTRPC();
  const queryClient = useQueryClient();
  const users = useQuery(trpc.admin.users.list.queryOptions());
  const refresh = () => queryClient.invalidateQueries({ queryKey: trpc.admin.users.list.queryKey() });
  const setRole = useMutation(trpc.admin.users.setRole.mutationOptions({ onSuccess: refresh }));
  const setDisabled = useMutation(trpc.admin.users.setDisabled.mutationOptions({ onSuccess: refresh }));
  return (
    <div className="space-y-6">
      <h1 className="text-2xl font-semibold">Accounts</h1>
      <NewAccount onCreated={refresh} />
      <ListView
        query={users}
        problem={setRole.error ?? setDisabled.error}
        columns={
          <>
            <Th>Name</Th>
            <Th>Email</Th>
            <Th>System role</Th>
            <Th>State</Th>
            <Th className="text-right">Actions</Th>
          </>
        }
        row={(u) => (
          <tr key={u.id}>
            <Td className="font-medium">{u.name}</Td>
            <Td>{u.email}</Td>
            <Td>
              <NativeSelect
                aria-label={`System role of ${u.name}`}
                className="w-44"
                value={u.role}
                disabled={u.id === selfId}
                onChange={(e) => setRole.mutate({ userId: u.id, role: e.target.value as SystemRole })}
              >
                {SYSTEM_ROLES.map((r) => (
                  <option key={r}>{r}</option>
                ))}
              </NativeSelect>
            </Td>
            <Td>{u.disabled ? <Badge tone="red">disabled</Badge> : <Badge tone="green">active</Badge>}</Td>
            <Td className="text-right">
              {u.id !== selfId && (
                <Button
                  variant="ghost"
                  size="sm"
                  onClick={() => setDisabled.mutate({ userId: u.id, disabled: !u.disabled })}
                >
                  {u.disabled ? `Enable ${u.name}` : `Disable ${u.name}`}
                </Button>
              )}
            </Td>
          </tr>
        )}
      />
    </div>
  );
}

function NewAccount({ onCreated }: { onCreated: () => void }) {
  const trpc = useTRPC();
  const [form, setForm] = useState({ name: "", email: "", password: "", role: "researcher" as SystemRole });
  const create = useMutation(
    trpc.admin.users.create.mutationOptions({
      onSuccess: () => {
        setForm({ name: "", email: "", password: "", role: "researcher" });
        onCreated();
      },
    }),
  );
  const set = (key: keyof typeof form) => (e: { target: { value: string } }) =>
    setForm({ ...form, [key]: e.target.value });
  const submit = (e: FormEvent) => {
    e.preventDefault();
    create.mutate(form);
  };
  return (
    <Card className="p-5">
      <h2 className="mb-3 font-semibold">Create an account</h2>
      <form onSubmit={submit} className="grid gap-3 sm:grid-cols-2 lg:grid-cols-5 lg:items-end">
        <Field label="Name" required error={fieldError(create.error, "name")}>
          {(p) => <Input {...p} value={form.name} onChange={set("name")} />}
        </Field>
        <Field label="Email" required error={fieldError(create.error, "email")}>
          {(p) => <Input {...p} type="email" value={form.email} onChange={set("email")} />}
        </Field>
        <Field label="Initial password" required error={fieldError(create.error, "password")}>
          {(p) => (
            <Input
              {...p}
              type="password"
              autoComplete="new-password"
              value={form.password}
              onChange={set("password")}
            />
          )}
        </Field>
        <Field label="System role">
          {(p) => (
            <NativeSelect {...p} value={form.role} onChange={set("role")}>
              {SYSTEM_ROLES.map((r) => (
                <option key={r}>{r}</option>
              ))}
            </NativeSelect>
          )}
        </Field>
        <Button type="submit" disabled={create.isPending}>
          Create account
        </Button>
      </form>
      {create.error && !create.error.data?.issues && (
        <div className="mt-3">
          <Problem error={create.error} />
        </div>
      )}
    </Card>
  );
}
