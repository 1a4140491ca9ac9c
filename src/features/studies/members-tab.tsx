"use client";
import { useMutation, useQuery, useQueryClient } from "@tanstack/react-query";
import { useState, type FormEvent } from "react";
import { STUDY_ROLES, studyRoleMay, type StudyRole } from "@/core/access/policy";
import { useTRPC } from "@/lib/trpc";
import { Button } from "@/ui/button";
import { Field, Input, NativeSelect } from "@/ui/field";
import { fieldError, Problem } from "@/ui/problem";
import { Badge, Card, ROLE_TONE } from "@/ui/surface";
import { ListView } from "@/ui/list-view";
import { Td, Th } from "@/ui/table";

const ROLE_HELP: Record<StudyRole, string> = {
  owner: "manages members and everything else",
  researcher: "designs experiments and reads data",
  wizard: "runs trials",
  observer: "watches and annotates",
};

export function MembersTab({ studyId, role }: { studyId: string; role: StudyRole }) {
  const trpc = useTRPC();
  const queryClient = useQueryClient();
  const members = useQuery(trpc.members.list.queryOptions({ studyId }));
  const manage = studyRoleMay(role, "member.manage");
  const refresh = () => queryClient.invalidateQueries({ queryKey: trpc.members.list.queryKey({ studyId }) });
  const changeRole = useMutation(trpc.members.changeRole.mutationOptions({ onSuccess: refresh }));
  const remove = useMutation(trpc.members.remove.mutationOptions({ onSuccess: refresh }));

  return (
    <div className="space-y-6">
      {manage && <InviteForm studyId={studyId} onAdded={refresh} />}
      <ListView
        query={members}
        problem={changeRole.error ?? remove.error}
        columns={
          <>
            <Th>Name</Th>
            <Th>Email</Th>
            <Th>Role</Th>
            {manage && <Th className="text-right">Actions</Th>}
          </>
        }
        row={(m) => (
          <tr key={m.userId}>
            <Td className="font-medium">{m.name}</Td>
            <Td>{m.email}</Td>
            <Td>
              {manage ? (
                <NativeSelect
                  aria-label={`Role of ${m.name}`}
                  className="w-40"
                  value={m.role}
                  onChange={(e) => changeRole.mutate({ studyId, userId: m.userId, role: e.target.value as StudyRole })}
                >
                  {STUDY_ROLES.map((r) => (
                    <option key={r} value={r}>
                      {r}
                    </option>
                  ))}
                </NativeSelect>
              ) : (
                <Badge tone={ROLE_TONE[m.role]}>{m.role}</Badge>
              )}
            </Td>
            {manage && (
              <Td className="text-right">
                <Button
                  variant="ghost"
                  size="sm"
                  aria-label={`Remove ${m.name}`}
                  onClick={() => remove.mutate({ studyId, userId: m.userId })}
                >
                  Remove
                </Button>
              </Td>
            )}
          </tr>
        )}
      />
    </div>
  );
}

function InviteForm({ studyId, onAdded }: { studyId: string; onAdded: () => void }) {
  const trpc = useTRPC();
  const [email, setEmail] = useState("");
  const [role, setRole] = useState<StudyRole>("researcher");
  const add = useMutation(
    trpc.members.add.mutationOptions({
      onSuccess: () => {
        setEmail("");
        onAdded();
      },
    }),
  );
  const submit = (e: FormEvent) => {
    e.preventDefault();
    add.mutate({ studyId, email, role });
  };
  return (
    <Card className="p-5">
      <h2 className="mb-3 font-semibold">Add a member</h2>
      <form onSubmit={submit} className="flex flex-wrap items-end gap-3">
        <div className="min-w-64 flex-1">
          <Field label="Member email" required error={fieldError(add.error, "email")}>
            {(p) => (
              <Input
                {...p}
                type="email"
                value={email}
                onChange={(e) => setEmail(e.target.value)}
                placeholder="name@lab.org"
              />
            )}
          </Field>
        </div>
        <div className="w-56">
          <Field label="Study role" hint={ROLE_HELP[role]}>
            {(p) => (
              <NativeSelect {...p} value={role} onChange={(e) => setRole(e.target.value as StudyRole)}>
                {STUDY_ROLES.map((r) => (
                  <option key={r} value={r}>
                    {r}
                  </option>
                ))}
              </NativeSelect>
            )}
          </Field>
        </div>
        <Button type="submit" disabled={add.isPending} className="mb-5">
          Add member
        </Button>
      </form>
      {add.error && !fieldError(add.error, "email") && <Problem error={add.error} />}
    </Card>
  );
}
