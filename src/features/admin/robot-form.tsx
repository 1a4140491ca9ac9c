"use client";
// Registering a robot, or changing one: its name, the plugin that drives it,
// its ways in, where its SSH secret is read (never the secret itself; the
// variables it may name are listed by name), and the studies that may use it.
import { useMutation, useQuery } from "@tanstack/react-query";
import { useState, type FormEvent } from "react";
import type { inferRouterOutputs } from "@trpc/server";
import { ROBOT_SECRET_PREFIX } from "@/core/robots/secrets";
import type { AppRouter } from "@/server/api/root";
import { useTRPC } from "@/lib/trpc";
import { Button } from "@/ui/button";
import { Field, Input, NativeSelect } from "@/ui/field";
import { fieldError, Problem } from "@/ui/problem";
import { Card } from "@/ui/surface";

export type RegisteredRobot = inferRouterOutputs<AppRouter>["robots"]["list"][number];

const ANY_PLUGIN = "";

function initial(robot: RegisteredRobot | null) {
  return {
    name: robot?.name ?? "",
    pluginRobotId: robot?.pluginRobotId ?? ANY_PLUGIN,
    rosbridgeUrl: robot?.rosbridgeUrl ?? "",
    sshHost: robot?.sshHost ?? "",
    sshPort: String(robot?.sshPort ?? 22),
    sshUser: robot?.sshUser ?? "",
    sshSecret: robot?.sshSecret ?? "",
    httpUrl: robot?.httpUrl ?? "",
    allStudies: robot?.allStudies ?? false,
    studyIds: robot?.studies.map((s) => s.id) ?? [],
  };
}

export function RobotForm({ robot, onDone }: { robot: RegisteredRobot | null; onDone: () => void }) {
  const trpc = useTRPC();
  const plugins = useQuery(trpc.plugins.list.queryOptions());
  const studies = useQuery(trpc.robots.studies.queryOptions());
  const secretNames = useQuery(trpc.robots.secretNames.queryOptions());
  const [form, setForm] = useState(() => initial(robot));
  const set = (changes: Partial<typeof form>) => setForm((f) => ({ ...f, ...changes }));
  const register = useMutation(trpc.robots.register.mutationOptions({ onSuccess: onDone }));
  const update = useMutation(trpc.robots.update.mutationOptions({ onSuccess: onDone }));
  const saving = robot ? update : register;
  const submit = (e: FormEvent) => {
    e.preventDefault();
    const input = { ...form, sshPort: Number(form.sshPort) };
    if (robot) update.mutate({ ...input, robotId: robot.id });
    else register.mutate(input);
  };
  const error = saving.error;
  const text = (key: "name" | "rosbridgeUrl" | "sshHost" | "sshPort" | "sshUser" | "sshSecret" | "httpUrl") => ({
    value: form[key],
    onChange: (e: { target: { value: string } }) => set({ [key]: e.target.value }),
  });
  return (
    <Card className="p-5">
      <h2 className="mb-3 font-semibold">{robot ? `Change ${robot.name}` : "Register a robot"}</h2>
      <form onSubmit={submit} className="grid gap-x-4 md:grid-cols-2">
        <Field
          label="Name"
          required
          error={fieldError(error, "name")}
          hint="How wizards know it, e.g. NAO by the window"
        >
          {(p) => <Input {...p} {...text("name")} />}
        </Field>
        <Field
          label="Plugin"
          error={fieldError(error, "pluginRobotId")}
          hint="The robot's plugin: trials of experiments for it may use this robot."
        >
          {(p) => (
            <NativeSelect {...p} value={form.pluginRobotId} onChange={(e) => set({ pluginRobotId: e.target.value })}>
              <option value={ANY_PLUGIN}>Any plugin (a simulated robot or stand-in)</option>
              {/* One entry per robotId: a physical robot serves every source's document of it. */}
              {plugins.data?.robots
                .filter((r) => r.isDefault)
                .map((r) => (
                  <option key={r.robotId} value={r.robotId}>
                    {r.name} ({r.robotId})
                  </option>
                ))}
            </NativeSelect>
          )}
        </Field>
        <Field label="Rosbridge address" error={fieldError(error, "rosbridgeUrl")} hint="e.g. ws://192.168.1.20:9090">
          {(p) => <Input {...p} {...text("rosbridgeUrl")} />}
        </Field>
        <Field
          label="HTTP address"
          error={fieldError(error, "httpUrl")}
          hint="For plugins that use the robot's REST API."
        >
          {(p) => <Input {...p} {...text("httpUrl")} />}
        </Field>
        <Field
          label="SSH host"
          error={fieldError(error, "sshHost")}
          hint="For NAOqi commands (postures, wake up, rest)."
        >
          {(p) => <Input {...p} {...text("sshHost")} />}
        </Field>
        <div className="grid grid-cols-[6rem_1fr] gap-3">
          <Field label="SSH port" error={fieldError(error, "sshPort")}>
            {(p) => <Input {...p} inputMode="numeric" {...text("sshPort")} />}
          </Field>
          <Field label="SSH user" error={fieldError(error, "sshUser")}>
            {(p) => <Input {...p} {...text("sshUser")} />}
          </Field>
        </div>
        <div className="md:col-span-2">
          <Field
            label="SSH secret (where to read it)"
            error={fieldError(error, "sshSecret")}
            hint={`env:${ROBOT_SECRET_PREFIX}NAME for a password in the runtime's environment (only such variables, never the platform's own settings), or file:/path for a private key. The secret itself is never stored. ${
              secretNames.data?.length
                ? `Variables this server has for robots: ${secretNames.data.join(", ")}.`
                : `This server has no variable starting ${ROBOT_SECRET_PREFIX} yet: set one where the platform is started.`
            }`}
          >
            {(p) => <Input {...p} placeholder={`env:${ROBOT_SECRET_PREFIX}NAO_WINDOW`} {...text("sshSecret")} />}
          </Field>
        </div>
        <fieldset className="md:col-span-2 space-y-2 text-sm">
          <legend className="mb-1 font-medium text-slate-700">Available to</legend>
          <label className="flex items-center gap-2">
            <input type="checkbox" checked={form.allStudies} onChange={(e) => set({ allStudies: e.target.checked })} />
            Every study
          </label>
          {!form.allStudies && (
            <div className="grid gap-1 sm:grid-cols-2">
              {studies.data?.map((s) => (
                <label key={s.id} className="flex items-center gap-2">
                  <input
                    type="checkbox"
                    checked={form.studyIds.includes(s.id)}
                    onChange={(e) =>
                      set({
                        studyIds: e.target.checked
                          ? [...form.studyIds, s.id]
                          : form.studyIds.filter((id) => id !== s.id),
                      })
                    }
                  />
                  {s.title}
                </label>
              ))}
            </div>
          )}
        </fieldset>
        <div className="mt-4 flex gap-2 md:col-span-2">
          <Button type="submit" disabled={saving.isPending}>
            {robot ? "Save" : "Register robot"}
          </Button>
          <Button variant="ghost" onClick={onDone}>
            Cancel
          </Button>
        </div>
      </form>
      {error &&
        !["name", "rosbridgeUrl", "httpUrl", "sshSecret", "sshHost", "sshUser", "sshPort"].some((k) =>
          fieldError(error, k),
        ) && <Problem error={error} />}
    </Card>
  );
}
